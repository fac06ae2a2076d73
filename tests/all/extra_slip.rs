//! The extra rigid slip per element (`[creepage] extra_slip`, CONTACT's EXRHS, E = 9): one that is
//! the same in every element is a creepage, and the models that cannot take it are refused.

use crate::common;
use creepbench::pipeline::resolve;
use creepbench::scene::Scene;
use std::fmt::Write;
use std::path::Path;

/// conformal_4 (CONTACT's conformal.inp case 4) in `dir` for `solver` with `creepage` lines and its own
/// extra-slip file of `(wx, wy)` in every element (none for `None`).
fn conformal(dir: &Path, name: &str, solver: &str, creepage: &str, w: Option<(f64, f64)>) -> Scene {
    let root = common::root().join("scenes/contact_public");
    std::fs::copy(root.join("conformal_4_h.csv"), dir.join("conformal_4_h.csv")).unwrap();
    let text = std::fs::read_to_string(root.join("conformal_4.toml")).unwrap();
    let start = text.find("[creepage]").unwrap();
    let end = text.find("[geometry]").unwrap();
    let mut extra = String::new();
    if let Some((wx, wy)) = w {
        let mut csv = String::from("ix,iy,wx,wy\n");
        for iy in 1..=39 {
            for ix in 1..=51 {
                let _ = writeln!(csv, "{ix},{iy},{wx:?},{wy:?}");
            }
        }
        std::fs::write(dir.join(format!("{name}_w.csv")), csv).unwrap();
        extra = format!("extra_slip = \"{name}_w.csv\"\n");
    }
    let text = format!("{}[creepage]\n{creepage}\n{extra}\n{}", &text[..start], &text[end..]);
    let text = text.replace("name = \"conformal_4\"", &format!("name = \"{name}\""));
    Scene::from_toml(&text.replace("[\"contact\"]", &format!("[\"{solver}\"]")), dir).unwrap()
}

/// The same extra slip in every element gives the results of that creepage (CONTACT adds EXRHS
/// to CKSI, CETA per element, `set_tang_rhs`) within round-off.
#[test]
fn a_uniform_extra_slip_is_a_creepage() {
    let dir = common::tempdir("extra_slip_uniform");
    let sweep = "kind = \"sweep\"\nover = \"cx\"";
    let extra = conformal(&dir, "extra", "contact", &format!("{sweep}\nat = [0.0]"), Some((0.002, -0.001)));
    let creep = conformal(&dir, "creep", "contact", &format!("{sweep}\nat = [0.002]\ncy = -0.001"), None);
    let (a, b) = (resolve(&extra).unwrap(), resolve(&creep).unwrap());
    assert!(a.extra_slip.is_some() && b.extra_slip.is_none());
    let (ha, hb) = (common::run(&a, "contact"), common::run(&b, "contact"));
    for column in ["fx_over_fn", "fy_over_fn", "mz_nmm"] {
        let (x, y) = (ha.column(column).unwrap()[0], hb.column(column).unwrap()[0]);
        assert!(x != 0.0 && (x - y).abs() <= 1e-9 * y.abs(), "{column}: {x} vs {y}");
    }
}

/// A simplified model takes the creepages only: a scene with an extra slip that asks for one is
/// refused naming it.
#[test]
fn the_simplified_models_refuse_an_extra_slip() {
    let dir = common::tempdir("extra_slip_refused");
    let scene =
        conformal(&dir, "refused", "fastsim", "kind = \"sweep\"\nover = \"cx\"\nat = [0.0]", Some((0.001, 0.0)));
    let e = resolve(&scene).expect_err("refused");
    assert!(e.to_string().contains("extra_slip"), "{e}");
}
