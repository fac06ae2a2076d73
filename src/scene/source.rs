//! Where one scene comes from: a scene file, or one point of a study file. Suites list them,
//! the pipeline loads them.

use crate::error::Error;
use crate::scene::study::StudyPoint;
use std::path::PathBuf;

/// One scene of a suite: a scene file, or one point of a study file ([`crate::scene::study`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SceneSource {
    /// The file it comes from.
    pub path: PathBuf,
    /// The scene's name: a study point's, or a scene file's `name` (its stem when it has none).
    pub name: String,
    /// A study point's scene table and its places in the studies (`None`: the file is the scene).
    pub study: Option<(toml::Table, Vec<StudyPoint>)>,
}

impl SceneSource {
    /// The scene as TOML text: the file's, or the study point's table (with its name).
    pub fn text(&self) -> Result<String, Error> {
        match &self.study {
            None => {
                Ok(crate::safety::read::read_text(&self.path, crate::safety::read::SCENE_LIMIT_BYTES, "scene file")?)
            }
            Some((doc, _)) => Ok(doc.to_string()),
        }
    }

    /// The scene as a TOML table: the file parsed, or the study point's table.
    pub fn table(&self) -> Result<toml::Table, Error> {
        match &self.study {
            None => Ok(crate::scene::reader::parse_toml(&self.text()?, self.path.display().to_string())?),
            Some((doc, _)) => Ok(doc.clone()),
        }
    }
}
