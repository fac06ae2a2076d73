//! Issue 46 item 3a: a Hertzian case whose load changes without a new discretisation (D = 0).
//! CONTACT's ellipse follows the curvatures to the new load while its grid stays the one the last
//! D >= 1 case sized; the imported scene must solve the same problem. Reference: CONTACT's own
//! output for a deck written by hand (reference/contact_handwritten/, its README).

use crate::common::{half_units, root};
use creepbench::comparison::references::contact_output::{self, CaseBody};
use creepbench::import::contact::scene::import_text;

#[test]
fn a_load_changed_without_a_new_grid_keeps_the_grid_and_follows_the_curvatures() {
    let dir = root().join("reference/contact_handwritten");
    let deck = std::fs::read_to_string(dir.join("hertz_load_change.inp")).unwrap();
    let printed = contact_output::read(&dir.join("hertz_load_change.ref_out")).unwrap();
    let imported = import_text("hertz_load_change.inp", "hz", &deck).unwrap();
    assert_eq!(imported.scenes.len(), 4);
    let tmp = tempfile::tempdir().unwrap();
    for (scene, out) in imported.scenes.iter().zip(&printed) {
        let CaseBody::Totals(t) = &out.body else { panic!("case {}: no totals", out.case) };
        for (name, text) in &scene.files {
            std::fs::write(tmp.path().join(name), text).unwrap();
        }
        let problem = creepbench::pipeline::load(&tmp.path().join(&scene.files[0].0), &[]).unwrap();
        // Case 2 keeps case 1's grid: SCALE 1.1 times case 1's semi-axes (2.835, 1.788 mm).
        if out.case == 2 {
            let g = &problem.grid;
            assert!((g.dx_mm - 0.2079).abs() < 5e-5 && (g.dy_mm - 0.1311).abs() < 5e-5, "{} {}", g.dx_mm, g.dy_mm);
        }
        let result = creepbench::pipeline::run(problem).unwrap();
        let h = &result.histories[0];
        let (row, fn_n) = (&h.rows[0], t.fn_n.value);
        let fy = row.fy_over_fn * fn_n;
        let mz = h.column(creepbench::history::MZ).unwrap()[0];
        let (dy, dm) = (half_units(fy, t.fy_n), half_units(mz, t.mz_nmm));
        println!("case {}: FY {fy:.2} ({dy:.2} half-units), MZ {mz:.1} ({dm:.2})", out.case);
        // The printed digits reproduced: within one half-unit of rounding and the solvers'
        // iteration tolerances (one more).
        assert!(dy <= 2.0 && dm <= 2.0, "case {}: FY {fy} vs {:?}, MZ {mz} vs {:?}", out.case, t.fy_n, t.mz_nmm);
    }
}
