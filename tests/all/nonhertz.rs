//! Issue 13, non-Hertzian contact: the exact solver against CONTACT on every case of
//! reference/contact_nonhertz (totals and fields), the element-wise `field` geometry against
//! CONTACT's own input, the orientation of a field, the equivalent ellipse, and the scene's input
//! errors and warnings. Every case's totals are also gated by `creepbench check` (tests/all/gate.rs).

use crate::common;
use common::*;
use creepbench::history::MZ;
use creepbench::physics::geometry::element::equivalent_ellipse;
use creepbench::physics::{ContactGeometry, Grid, HertzContact, HertzEllipse, Material};
use creepbench::problem::Problem;
use creepbench::scene::Scene;

const CASES: [&str; 5] =
    ["nh_flat_sweep_cx", "nh_two_sweep_cy_cs", "nh_asym_step_combined", "nh_kink_sine_cx", "nh_two_fn_ramp"];

/// Worst |Δ| of fx/fn, fy/fn and mz/(FN a) of the exact solver against CONTACT's history.
fn worst_against_contact(p: &Problem, case: &str) -> [f64; 3] {
    let ours = run(p, "contact");
    let theirs = creepbench::comparison::references::contact::read_history(
        &root().join(format!("reference/contact_nonhertz/{case}.csv")),
        0,
        &[MZ],
    )
    .unwrap();
    assert_eq!(ours.rows.len(), theirs.rows.len(), "{case}: every step");
    let a_mm = p.hertz().a_mm;
    let mut worst = [0.0f64; 3];
    let (mo, mt) = (ours.column(MZ).unwrap(), theirs.column(MZ).unwrap());
    for (k, (o, t)) in ours.rows.iter().zip(&theirs.rows).enumerate() {
        assert_eq!(o.sample.step, t.sample.step);
        let d = [
            (o.fx_over_fn - t.fx_over_fn).abs(),
            (o.fy_over_fn - t.fy_over_fn).abs(),
            (mo[k] - mt[k]).abs() / (t.sample.fn_n * a_mm),
        ];
        for q in 0..3 {
            worst[q] = worst[q].max(d[q]);
        }
    }
    worst
}

/// Every CONTACT non-Hertzian case within 1e-5 at every step in fx/fn, fy/fn and mz/(FN a):
/// flat-bottomed, two patches, asymmetric, kinked, and two patches merging under a load ramp.
#[test]
fn exact_solver_matches_contact_on_every_nonhertz_case() {
    for case in CASES {
        let sc = Scene::from_file(&root().join(format!("scenes/nonhertz/{case}.toml"))).unwrap();
        let p = creepbench::pipeline::resolve(&sc).unwrap();
        assert_eq!(p.geometry.kind(), "profile");
        assert!(p.warnings.is_empty(), "{case}: {:?}", p.warnings);
        let w = worst_against_contact(&p, case);
        println!("{case:<22} fx {:.1e}  fy {:.1e}  mz/(FN a) {:.1e}", w[0], w[1], w[2]);
        assert!(w.iter().all(|&d| d < 1e-5), "{case}: {w:?}");
    }
}

/// Pressure, tractions and element states against CONTACT's field files, element by element:
/// two patches merged under the ramp (steps 40, 80) and the asymmetric combined step (25, 48).
#[test]
fn nonhertz_fields_match_contact() {
    for case in ["nh_two_fn_ramp", "nh_asym_step_combined"] {
        let (n, worst) = compare_fields_with_contact(
            &format!("scenes/nonhertz/{case}.toml"),
            &format!("reference/contact_nonhertz/{case}_field.csv"),
            1e-4,
        );
        println!("{case}: {n} elements, largest difference {worst:.2e} of mu p_max");
        assert!(n > 1000);
    }
}

/// The undeformed distance CONTACT was given element by element (IBASE = 9 in the case's
/// .inp), as a `kind = "field"` geometry: the same results as the profile, within 1e-5.
#[test]
fn field_geometry_from_contacts_input_matches_contact() {
    let case = "nh_asym_step_combined";
    let inp = std::fs::read_to_string(root().join(format!("reference/contact_nonhertz/{case}.inp"))).unwrap();
    let lines: Vec<&str> = inp.lines().collect();
    let at = lines.iter().position(|l| l.contains("IBASE, IPLAN")).unwrap();
    let (mx, my) = (32, 22);
    let h: Vec<f64> = lines[at + 1..]
        .iter()
        .flat_map(|l| l.split_whitespace().map_while(|v| v.parse::<f64>().ok()))
        .take(mx * my)
        .collect();
    assert_eq!(h.len(), mx * my);
    let dir = tempdir("nonhertz_field");
    let mut csv = String::from("ix,iy,h_mm\n");
    for (k, v) in h.iter().enumerate() {
        csv += &format!("{},{},{v}\n", k % mx + 1, k / mx + 1);
    }
    std::fs::write(dir.join("h.csv"), csv).unwrap();
    let profile_scene = std::fs::read_to_string(root().join(format!("scenes/nonhertz/{case}.toml"))).unwrap();
    let start = profile_scene.find("[geometry]").unwrap();
    let end = profile_scene.find("[material]").unwrap();
    let text = format!(
        "{}[geometry]\nkind = \"field\"\nfield = \"h.csv\"\n\n{}",
        &profile_scene[..start],
        &profile_scene[end..]
    )
    .replace("file = \"nh_asym", &format!("file = \"{}/scenes/nonhertz/nh_asym", root().display()));
    let p = creepbench::pipeline::resolve(&Scene::from_toml(&text, &dir).unwrap()).unwrap();
    assert_eq!(p.geometry.kind(), "field");
    // scene.json hands the shape to external models in CONTACT's order, as given.
    let resolved = creepbench::problem::ResolvedScene::of(&p, &[]);
    assert_eq!(resolved.undeformed_distance_mm.as_deref(), Some(h.as_slice()));
    assert_eq!(resolved.grid_edges_mm, Some([[-8.0, 8.0], [-6.0, 5.0]]));
    // The profile scene's h is CONTACT's input to its printed digits (a1 to 10 digits).
    let profile =
        creepbench::pipeline::resolve(&Scene::from_file(&root().join(format!("scenes/nonhertz/{case}.toml"))).unwrap())
            .unwrap();
    let from_profile = creepbench::problem::ResolvedScene::of(&profile, &[]).undeformed_distance_mm.unwrap();
    let worst = from_profile.iter().zip(&h).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    println!("profile h against CONTACT's input: worst {worst:.1e} mm");
    assert!(worst < 1e-9, "{worst}");
    let w = worst_against_contact(&p, case);
    println!("field geometry: fx {:.1e}  fy {:.1e}  mz/(FN a) {:.1e}", w[0], w[1], w[2]);
    assert!(w.iter().all(|&d| d < 1e-5), "{w:?}");
}

/// A field's ix runs along CONTACT's x: a bowl centred at x_C = +2 mm carries its load there, at
/// grid x = −2 mm (the grid's x is −x_C); moved by 2 mm (four elements) the same contact gives the
/// same force and a moment larger by 2 mm × fy (the references' sign: mz = x_C fy − y fx).
#[test]
fn field_index_runs_along_contacts_x() {
    let (mx, my) = (24, 16);
    let bowl = |x_c: f64| {
        let dir = tempdir(&format!("nonhertz_orientation_{x_c}"));
        let mut csv = String::from("ix,iy,h_mm\n");
        for iy in 1..=my {
            for ix in 1..=mx {
                let (x, y) = (-6.0 + (ix as f64 - 0.5) * 0.5, -4.0 + (iy as f64 - 0.5) * 0.5);
                csv += &format!("{ix},{iy},{}\n", 0.002 * (x - x_c) * (x - x_c) + 0.004 * y * y);
            }
        }
        std::fs::write(dir.join("h.csv"), csv).unwrap();
        let text = format!(
            "name = \"bowl\"\nsolvers = [\"contact\"]\n[contact]\nfn_n = 20000.0\nmu = 0.3\n[geometry]\nkind = \"field\"\nfield = \"h.csv\"\n[material]\ng_mpa = 82000.0\npoisson = 0.28\n[grid]\nmx = {mx}\nmy = {my}\nx_mm = [-6.0, 6.0]\ny_mm = [-4.0, 4.0]\n[creepage]\nkind = \"sweep\"\nover = \"cy\"\nfrom = 0.001\nto = 0.001\npoints = 1\n"
        );
        creepbench::pipeline::resolve(&Scene::from_toml(&text, &dir).unwrap()).unwrap()
    };
    let p = bowl(2.0);
    assert!(p.warnings.is_empty(), "{:?}", p.warnings);
    let planform = p.geometry.planform(&p.grid, 20000.0, p.model.pressure);
    let (x, _) = p.grid.centres();
    let centroid: f64 =
        planform.pressure_mpa.iter().zip(&x).map(|(p, x)| p * x).sum::<f64>() / planform.pressure_sum_mpa;
    assert!((centroid + 2.0).abs() < 1e-9, "pressure centroid at grid x = {centroid} (expected −2)");
    let (h2, h0) = (run(&p, "contact"), run(&bowl(0.0), "contact"));
    let fy = h2.rows[0].fy_over_fn * 20000.0;
    let arm = (h2.column(MZ).unwrap()[0] - h0.column(MZ).unwrap()[0]) / fy;
    println!("fy {fy:.3} N; the moment moves by {arm:.6} mm x fy");
    assert!((h2.rows[0].fy_over_fn - h0.rows[0].fy_over_fn).abs() < 1e-7 && fy > 0.0);
    assert!((arm - 2.0).abs() < 1e-4, "arm {arm}");
}

/// Kik–Piotrowski's equivalent ellipse of a Hertzian pressure on the grid is the ellipse itself,
/// within the grid's resolution (one element).
#[test]
fn equivalent_ellipse_of_a_hertz_contact_is_its_ellipse() {
    let e = HertzContact { a_mm: 8.56, b_mm: 4.08, fn_n: 100_000.0 };
    let grid = Grid::new(88, 88, 1.1 * e.a_mm, 1.1 * e.b_mm);
    let m = Material::from_g(82000.0, 0.28);
    let h = HertzEllipse { nominal: e }.undeformed_distance_mm(&grid, e.fn_n, &m);
    let geometry =
        creepbench::physics::geometry::ElementGeometry::new("field", h, grid.clone(), &m, e.fn_n, None).unwrap();
    let c = geometry.nominal_contact();
    let q = equivalent_ellipse(&grid, &c.pn_mpa, e.fn_n).unwrap();
    println!("equivalent ellipse {:.4} x {:.4} mm (Hertz 8.56 x 4.08)", q.a_mm, q.b_mm);
    assert!((q.a_mm - e.a_mm).abs() < grid.dx_mm && (q.b_mm - e.b_mm).abs() < grid.dy_mm, "{q:?}");
    assert_eq!(c.edge_load_share, 0.0);
}

/// Bad geometry input: clear errors naming the field, never NaN; a grid that cuts the contact
/// gives a warning with the share of the load on its edge.
#[test]
fn nonhertz_input_errors_and_warnings() {
    let base = std::fs::read_to_string(root().join("scenes/nonhertz/nh_flat_sweep_cx.toml")).unwrap();
    let dir = root().join("scenes/nonhertz");
    let resolve = |text: &str| Scene::from_toml(text, &dir).and_then(|s| creepbench::pipeline::resolve(&s));
    let err = |text: &str| resolve(text).expect_err("an input error").to_string();
    // A profile that does not cover the grid.
    let e = err(&base.replace("y_mm = [-7.5, 7.5]", "y_mm = [-20.0, 20.0]"));
    assert!(e.contains("geometry.profile") && e.contains("covering"), "{e}");
    // Ellipse keys beside a geometry given per element.
    let e = err(&base.replace("mu = 0.4", "mu = 0.4\na_mm = 8.0"));
    assert!(e.contains("contact.a_mm"), "{e}");
    // Edges only on one axis, reversed edges, edges for an ellipse.
    let e = err(&base.replace("y_mm = [-7.5, 7.5]\n", ""));
    assert!(e.contains("grid.y_mm") && e.contains("missing"), "{e}");
    let e = err(&base.replace("x_mm = [-7.0, 7.0]", "x_mm = [7.0, -7.0]"));
    assert!(e.contains("grid.x_mm") && e.contains("low < high"), "{e}");
    let hertz = scene_text("h", r#"["contact"]"#, 0.4, 8, "kind = \"step\"\nc = 0.001\nsteps = 2", "");
    // An ellipse on a window of its own (CONTACT's grid kept by D = 0): accepted, its grid the
    // window; with `scale` beside the edges, refused.
    let p = resolve(&hertz.replace("my = 8", "my = 8\nx_mm = [-1.0, 1.0]\ny_mm = [-2.0, 2.0]")).unwrap();
    assert!((p.grid.dx_mm - 0.25).abs() < 1e-12 && (p.grid.dy_mm - 0.5).abs() < 1e-12, "{:?}", p.grid);
    let e = err(&hertz.replace("my = 8", "my = 8\nx_mm = [-1.0, 1.0]\ny_mm = [-2.0, 2.0]\nscale = 1.2"));
    assert!(e.contains("scale") && e.contains("explicit edges"), "{e}");
    // A missing profile file, a profile not increasing in y.
    let e = err(&base.replace("profile_flat.csv", "no_such_profile.csv"));
    assert!(e.contains("geometry.profile"), "{e}");
    let tmp = tempdir("nonhertz_profile");
    std::fs::write(tmp.join("p.csv"), "y_mm,g_mm\n-10,1\n0,0\n0,0.5\n10,1\n").unwrap();
    let text = base.replace(
        "\"../../reference/contact_nonhertz/profile_flat.csv\"",
        &format!("\"{}\"", tmp.join("p.csv").display()),
    );
    let e = err(&text);
    assert!(e.contains("line 4") && e.contains("strictly increasing"), "{e}");
    // A field that misses an element.
    std::fs::write(tmp.join("f.csv"), "ix,iy,h_mm\n1,1,0.0\n").unwrap();
    let field = base.replace("kind = \"profile\"\na1_per_mm = 0.001086956522\nprofile", "kind = \"field\"\nfield");
    let e = err(&field.replace(
        "\"../../reference/contact_nonhertz/profile_flat.csv\"",
        &format!("\"{}\"", tmp.join("f.csv").display()),
    ));
    assert!(e.contains("geometry.field") && e.contains("every element"), "{e}");
    // A grid that cuts the contact: a warning with the share of the load on its edge.
    let p = resolve(&base.replace("y_mm = [-7.5, 7.5]", "y_mm = [-4.0, 4.0]").replace("my = 30", "my = 16")).unwrap();
    assert!(p.warnings.iter().any(|w| w.contains("grid's edge") && w.contains("% of the load")), "{:?}", p.warnings);
}

/// The profile and field readers name the line of the file: the CSV reader skips empty lines, so
/// a row after them is not on line (its index + 2), where the errors used to point.
#[test]
fn geometry_errors_name_the_line_after_empty_lines() {
    let base = std::fs::read_to_string(root().join("scenes/nonhertz/nh_flat_sweep_cx.toml")).unwrap();
    let dir = root().join("scenes/nonhertz");
    let err = |text: &str| {
        let e = Scene::from_toml(text, &dir).and_then(|s| creepbench::pipeline::resolve(&s));
        e.expect_err("an input error").to_string()
    };
    let tmp = tempdir("nonhertz_lines");
    let with_file = |text: &str, file: &str| {
        text.replace(
            "\"../../reference/contact_nonhertz/profile_flat.csv\"",
            &format!("\"{}\"", tmp.join(file).display()),
        )
    };
    // y_mm not increasing on line 6, after two empty lines (the row index + 2 is 4).
    std::fs::write(tmp.join("p.csv"), "y_mm,g_mm\n-10,1\n\n\n0,0\n0,0.5\n10,1\n").unwrap();
    let e = err(&with_file(&base, "p.csv"));
    // The message names the file as well as the key.
    assert!(e.contains("p.csv) line 6` = y_mm = 0 after 0") && e.contains("geometry.profile ("), "{e}");
    // An element given twice, on line 4 right after an empty line (CRLF line ends).
    std::fs::write(tmp.join("f.csv"), "ix,iy,h_mm\r\n1,1,0.0\r\n\r\n1,1,0.0\r\n").unwrap();
    let field = base.replace("kind = \"profile\"\na1_per_mm = 0.001086956522\nprofile", "kind = \"field\"\nfield");
    let e = err(&with_file(&field, "f.csv"));
    assert!(e.contains("f.csv) line 4` = ix = 1, iy = 1: allowed: every element once"), "{e}");
    assert!(e.contains("geometry.field ("), "{e}");
    // A cell that is not a number on line 5, the first row after the header's empty lines.
    std::fs::write(tmp.join("g.csv"), "\nix,iy,h_mm\n\n\nx,1,0.0\n").unwrap();
    let e = err(&with_file(&field, "g.csv"));
    assert!(e.contains("g.csv) line 5 column ix` = \"x\""), "{e}");
}
