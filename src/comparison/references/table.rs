//! CONTACT's own test table (reference/contact_table: `testbank/test_table_mx11.ref_fx` of its
//! repository, the output of `src/test_table.f90`): 3220 steady cases over a/b, spin level,
//! direction and magnitude, read into the case-set form of [`EnvelopeCases`] under the names of
//! the study `scenes/table/study_test_table.toml` (`tt_<case>_<angle>`, sweep point k = the k-th
//! magnitude). Compared and gated as the envelope (the exact solver to 1e-5).

use super::envelope::EnvelopeCases;
use super::read;
use crate::comparison::against::Against;
use crate::error::{Error, FormatError};
use crate::history::{History, Row, MZ};
use crate::problem::Sample;
use std::path::Path;

/// CONTACT's exact theory on its test table.
pub const TABLE: Against = Against::Reference("CONTACT test table");

/// The table's file, inside the reference folder.
pub const FILE: &str = "contact_table/test_table_mx11.ref_fx";

/// test_table.f90's cases: a/b with the semi-axis a [mm], spin levels, directions [deg] (their
/// scene-name labels), the number of magnitudes, FN [N] and μ.
const ELLIP_A_MM: [(f64, f64); 5] = [(0.2, 4.0), (0.5, 6.0), (1.0, 9.0), (2.0, 12.0), (5.0, 20.0)];
const SPIN: [f64; 4] = [0.0, 0.5, 1.0, 2.0];
const ANGLES: [&str; 7] = ["m90", "m60", "m30", "0", "30", "60", "90"];
const MAGNITUDES: usize = 23;
const FN_N: f64 = 82000.0;
const MU: f64 = 0.3;

/// The study's scene name of one a/b, spin level and direction.
pub fn scene_name(ellip: f64, spin: f64, angle: &str) -> String {
    let label = |v: f64| crate::scene::study::label_of(&toml::Value::Float(v));
    format!("tt_ab{}_sp{}_{angle}", label(ellip), label(spin))
}

/// `Fx=…, Fy=…, Mz=…, %Slip=…` → (Fx, Fy, Mz).
fn parse_case(line: &str) -> Option<(f64, f64, f64)> {
    let mut values = line.split(',').map(|part| part.split('=').nth(1).and_then(|v| v.trim().parse::<f64>().ok()));
    Some((values.next()??, values.next()??, values.next()??))
}

/// Load the table (an empty set where the folder holds no table).
pub fn load(dir: &Path) -> Result<EnvelopeCases, Error> {
    let path = dir.join(FILE);
    let mut out = EnvelopeCases { against: Some(TABLE), ..EnvelopeCases::default() };
    if !path.is_file() {
        return Ok(out);
    }
    let text = read(&path)?;
    let bad = |line: usize, value: String| Error::Format {
        path: path.clone(),
        source: FormatError::Value { line, column: "case".into(), value, what: "3220 lines Fx=…, Fy=…, Mz=…" },
    };
    let cases: Vec<(usize, &str)> =
        text.lines().enumerate().map(|(n, l)| (n + 1, l)).filter(|(_, l)| l.starts_with("Fx=")).collect();
    let expected = ELLIP_A_MM.len() * SPIN.len() * ANGLES.len() * MAGNITUDES;
    if cases.len() != expected {
        return Err(bad(0, format!("{} case lines", cases.len())));
    }
    let mut lines = cases.into_iter();
    for (ellip, a_mm) in ELLIP_A_MM {
        let cp_mm = (a_mm * a_mm / ellip).sqrt();
        for spin in SPIN {
            for angle in ANGLES {
                let mut h = History::new("CONTACT", &[MZ]);
                for step in 1..=MAGNITUDES {
                    let (n, line) = lines.next().ok_or_else(|| bad(0, "too few case lines".into()))?;
                    let (fx, fy, mz) = parse_case(line).ok_or_else(|| bad(n, line.chars().take(60).collect()))?;
                    // Forces on body 1 over mu FN, moment over mu FN cp: flipped and scaled.
                    h.rows.push(Row {
                        sample: Sample::given(step, 0.0, f64::NAN, f64::NAN, f64::NAN, FN_N, MU).into(),
                        fx_over_fn: -MU * fx,
                        fy_over_fn: -MU * fy,
                        extra: vec![-MU * FN_N * cp_mm * mz],
                    });
                }
                let name = scene_name(ellip, spin, angle);
                out.notes.insert(name.clone(), format!("a/b {ellip}, spin level {spin}, direction {angle}°"));
                out.histories.insert(name, h);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_lines() {
        assert_eq!(scene_name(0.2, 0.5, "m90"), "tt_ab0p2_sp0p5_m90");
        assert_eq!(scene_name(1.0, 2.0, "30"), "tt_ab1_sp2_30");
        assert_eq!(
            parse_case("Fx=  -0.242187, Fy=  -0.106188, Mz=   0.019918, %Slip=  17.1"),
            Some((-0.242187, -0.106188, 0.019918))
        );
        assert_eq!(parse_case("iell=1, a/b=  0.2: rho=   1772."), None);
    }
}
