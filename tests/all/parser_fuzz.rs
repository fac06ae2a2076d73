//! A fuzz-style test of the scene parser: thousands of random and mutated inputs, no panic;
//! every rejection is an input error naming a field.

use creepbench::scene::Scene;
use proptest::prelude::*;
use std::path::Path;

use crate::common;

/// The thesis scene sine_f30_mu10 (a point of a study) as scene text.
fn base() -> &'static str {
    static BASE: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    BASE.get_or_init(|| common::suite_scene_text("thesis", "sine_f30_mu10"))
}

fn parse(text: &str) {
    match Scene::from_toml(text, Path::new("/nonexistent")) {
        Ok(scene) => {
            if let Err(e) = creepbench::pipeline::resolve(&scene) {
                assert!(!e.field.is_empty(), "resolve error without a field: {e}");
            }
        }
        Err(e) => assert!(!e.field.is_empty() && !e.allowed.is_empty(), "error without field/allowed: {e:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Arbitrary text.
    #[test]
    fn random_text_never_panics(s in "\\PC{0,400}") {
        parse(&s);
    }

    /// The thesis scene with one line replaced by random bytes, or a value replaced.
    #[test]
    fn mutated_scene_never_panics(line in 0usize..40, junk in "[ -~]{0,40}", value in prop_oneof![
        Just("nan".to_string()), Just("inf".to_string()), Just("-inf".to_string()), Just("-1".to_string()),
        Just("0".to_string()), Just("1e308".to_string()), Just("\"x\"".to_string()), Just("[]".to_string()),
        Just("{}".to_string()), Just("true".to_string()), Just("99999999999999999999".to_string()),
        "-?[0-9]{1,6}(\\.[0-9]{1,4})?(e-?[0-9]{1,3})?",
    ]) {
        let lines: Vec<&str> = base().lines().collect();
        let k = line % lines.len();
        let mut a = lines.clone();
        let replaced = match lines[k].split_once(" = ") {
            Some((key, _)) => format!("{key} = {value}"),
            None => junk.clone(),
        };
        a[k] = &replaced;
        parse(&a.join("\n"));
        let mut b = lines.clone();
        b[k] = &junk;
        parse(&b.join("\n"));
    }
}
