//! A thin compressible sheet (CONTACT's B = 1, `[material] sheet_flexibility_mm3_per_n`) in
//! module 3: a deck written by hand (reference/contact_handwritten/sheet_hertz.inp, its README),
//! imported, solved and compared with CONTACT's printed output; exported back with B = 1 and
//! FLXZ. Module 1's sheet is gated by `scenes/wheelrail/testbank_21`.

use crate::common::{half_units, root};
use creepbench::comparison::references::contact_output::{self, CaseBody};
use creepbench::import::contact::scene::import_text;

/// The deck's three cases (steady rolling with the sheet, frictionless compression with it, the
/// same rolling without it) solved as imported: FY, MZ (as the reader gives them, in the
/// project's frame), PMAX and the contact's element count CONTACT's.
#[test]
fn a_hertzian_contact_on_a_compressible_sheet_is_contacts() {
    let dir = root().join("reference/contact_handwritten");
    let deck = std::fs::read_to_string(dir.join("sheet_hertz.inp")).unwrap();
    let printed = contact_output::read(&dir.join("sheet_hertz.ref_out")).unwrap();
    let imported = import_text("sheet_hertz.inp", "sheet", &deck).unwrap();
    assert_eq!((imported.scenes.len(), printed.len()), (3, 3));
    let tmp = tempfile::tempdir().unwrap();
    let mut pmax = Vec::new();
    for (scene, out) in imported.scenes.iter().zip(&printed) {
        let CaseBody::Totals(t) = &out.body else { panic!("case {}: no totals", out.case) };
        for (name, text) in &scene.files {
            std::fs::write(tmp.path().join(name), text).unwrap();
        }
        let problem = creepbench::pipeline::load(&tmp.path().join(&scene.files[0].0), &[]).unwrap();
        let sheet = problem.material.sheet_mm3_per_n;
        assert_eq!(sheet, if out.case == 3 { 0.0 } else { 7.429e-5 }, "case {}", out.case);
        let result = creepbench::pipeline::run(problem).unwrap();
        let h = &result.histories[0];
        let row = &h.rows[0];
        let fy = row.fy_over_fn * t.fn_n.value;
        let mz = h.column(creepbench::history::MZ).unwrap()[0];
        let p = h.column("pn_max_mpa").unwrap()[0];
        let worst = [half_units(fy, t.fy_n), half_units(mz, t.mz_nmm), half_units(p, t.pn_max_mpa)];
        println!("case {}: FY {fy:.2}, MZ {mz:.2}, PMAX {p:.2}: {worst:.2?} half-units", out.case);
        // The printed digits: one half-unit of rounding and the solvers' tolerances (one more).
        assert!(worst.iter().all(|&w| w <= 2.0), "case {}: {worst:?} {t:?}", out.case);
        let s = t.statistics.unwrap();
        let counts = h.column("n_adhesion").unwrap()[0] as u32 + h.column("n_slip").unwrap()[0] as u32;
        assert_eq!(counts, s.ncon, "case {}", out.case);
        pmax.push(p);
    }
    // The sheet spreads the load: PMAX 416 MPa against the half-space's 938.
    assert!(pmax[0] < 0.5 * pmax[2], "{pmax:?}");
}

/// `export contact` writes B = 1 and FLXZ after POISS, GG, and reads back to the same sheet.
#[test]
fn a_sheet_exports_as_b1_with_flxz_and_reads_back() {
    let dir = root().join("reference/contact_handwritten");
    let deck = std::fs::read_to_string(dir.join("sheet_hertz.inp")).unwrap();
    let imported = import_text("sheet_hertz.inp", "sheet", &deck).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let scene = &imported.scenes[0];
    for (name, text) in &scene.files {
        std::fs::write(tmp.path().join(name), text).unwrap();
    }
    let problem = creepbench::pipeline::load(&tmp.path().join(&scene.files[0].0), &[]).unwrap();
    creepbench::export::contact::check(&problem).unwrap();
    let text = creepbench::export::contact::module3_input(&problem);
    assert!(text.lines().any(|l| l.trim_start().starts_with("21") && l.contains("P-B-T-N-F-S")), "{text}");
    assert!(text.contains("7.429e-5") && text.contains("FLXZ"), "{text}");
    let again = import_text("exported.inp", "again", &text).unwrap();
    let tmp2 = tempfile::tempdir().unwrap();
    for (name, text) in &again.scenes[0].files {
        std::fs::write(tmp2.path().join(name), text).unwrap();
    }
    let back = creepbench::pipeline::load(&tmp2.path().join(&again.scenes[0].files[0].0), &[]).unwrap();
    assert_eq!(back.material.sheet_mm3_per_n, 7.429e-5);
}
