//! Issue 31 item 2, what a machine can check of the figures: the report built from golden/ (every
//! figure the shipped suites draw, but the cost plot, which needs timings), each SVG parsed and
//! rendered (resvg), each model drawn in one colour and marker in every figure, no two series of
//! a figure alike, tick labels apart (text extents from font size and character count), no "-0",
//! axis titles with a unit, legends and colour bars outside the plot areas, patch maps with a key.
//! Plus a user's own model beside the built-in ones, and the cost plot's log axes.

use crate::common;
use common::{root, tempdir};
use creepbench::report::plot::{line_chart, Axis, Series};
use quick_xml::events::Event;
use std::collections::BTreeMap;

/// One element: name, attributes, text content, and the class and attributes of its enclosing
/// groups (innermost last).
struct Element {
    name: String,
    attrs: BTreeMap<String, String>,
    text: String,
    groups: Vec<BTreeMap<String, String>>,
}

impl Element {
    fn attr(&self, key: &str) -> &str {
        self.attrs.get(key).map(String::as_str).unwrap_or("")
    }
    fn num(&self, key: &str) -> f64 {
        self.attr(key).parse().unwrap_or_else(|_| panic!("<{}> {key}={:?}", self.name, self.attr(key)))
    }
    fn class(&self) -> &str {
        self.attr("class")
    }
    /// The innermost enclosing group of `class` (its attributes).
    fn within(&self, class: &str) -> Option<&BTreeMap<String, String>> {
        self.groups.iter().rev().find(|g| g.get("class").is_some_and(|c| c == class))
    }
}

/// Every element of a well-formed SVG, with its enclosing groups.
fn parse(file: &str, svg: &str) -> Vec<Element> {
    let mut reader = quick_xml::Reader::from_str(svg);
    let mut stack: Vec<(String, BTreeMap<String, String>)> = Vec::new();
    let mut out: Vec<Element> = Vec::new();
    let mut open_text: Option<usize> = None;
    loop {
        let ev = reader.read_event().unwrap_or_else(|e| panic!("{file}: not well-formed XML: {e}"));
        let (e, opens) = match &ev {
            Event::Start(e) => (e.clone(), true),
            Event::Empty(e) => (e.clone(), false),
            Event::Text(t) => {
                if let Some(k) = open_text {
                    out[k].text.push_str(&t.xml_content().unwrap());
                }
                continue;
            }
            Event::GeneralRef(r) => {
                if let Some(k) = open_text {
                    let entity = String::from_utf8(r.to_vec()).unwrap();
                    let c = match entity.as_str() {
                        "amp" => "&",
                        "lt" => "<",
                        "gt" => ">",
                        "quot" => "\"",
                        other => panic!("{file}: entity &{other};"),
                    };
                    out[k].text.push_str(c);
                }
                continue;
            }
            Event::End(_) => {
                stack.pop();
                open_text = None;
                continue;
            }
            Event::Eof => break,
            _ => continue,
        };
        let name = String::from_utf8(e.name().as_ref().to_vec()).unwrap();
        let attrs: BTreeMap<String, String> = e
            .attributes()
            .map(|a| {
                let a = a.unwrap();
                (String::from_utf8(a.key.as_ref().to_vec()).unwrap(), a.unescape_value().unwrap().to_string())
            })
            .collect();
        let groups = stack.iter().filter(|(n, _)| n == "g").map(|(_, a)| a.clone()).collect();
        out.push(Element { name: name.clone(), attrs: attrs.clone(), text: String::new(), groups });
        if opens {
            open_text = (name == "text").then_some(out.len() - 1);
            stack.push((name, attrs));
        }
    }
    assert!(stack.is_empty(), "{file}: unclosed elements {stack:?}");
    out
}

/// (x, y) of a `translate(x,y)` transform.
fn translate(attrs: &BTreeMap<String, String>) -> (f64, f64) {
    let t = attrs.get("transform").expect("a transform");
    let inner = t.trim_start_matches("translate(").trim_end_matches(')');
    let (x, y) = inner.split_once(',').unwrap();
    (x.parse().unwrap(), y.parse().unwrap())
}

/// Rendered with resvg: the page is drawn, and every series colour appears in it.
fn render(file: &str, svg: &str, colors: &[String]) {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("{file}: resvg cannot read it: {e}"));
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).expect("a page size");
    resvg::render(&tree, resvg::tiny_skia::Transform::default(), &mut pixmap.as_mut());
    let pixels: Vec<[u8; 3]> = pixmap.pixels().iter().map(|p| [p.red(), p.green(), p.blue()]).collect();
    let inked = pixels.iter().filter(|p| **p != [255, 255, 255]).count();
    assert!(inked > 2000, "{file}: only {inked} pixels drawn");
    for c in colors {
        let rgb: Vec<u8> = (0..3).map(|k| u8::from_str_radix(&c[1 + 2 * k..3 + 2 * k], 16).unwrap()).collect();
        assert!(pixels.iter().any(|p| p[..] == rgb[..]), "{file}: colour {c} drawn nowhere");
    }
}

/// Estimated text width as the figures estimate it: 0.6 em per character.
fn width(text: &str, font_px: f64) -> f64 {
    0.6 * font_px * text.chars().count() as f64
}

/// What [`check`] found in one figure: the style of every model it draws.
type Styles = BTreeMap<(String, bool), (String, String)>;

/// Every machine-checkable property of one figure; returns the styles of the models it draws.
fn check(file: &str, svg: &str) -> Styles {
    let elements = parse(file, svg);
    let root = &elements[0];
    assert_eq!(root.name, "svg", "{file}");
    assert!(root.num("width") > 100.0 && root.num("height") > 100.0, "{file}");

    // Series: drawn in the colour they declare, one style per model, no two models alike, no
    // model twice in a panel.
    let mut styles = Styles::new();
    let mut by_look: BTreeMap<(String, String), String> = BTreeMap::new();
    let mut in_panel: BTreeMap<(String, String), usize> = BTreeMap::new();
    for e in elements.iter().filter(|e| e.class() == "series") {
        let (model, color, marker) = (e.attr("data-model"), e.attr("data-color"), e.attr("data-marker"));
        let reference = e.attr("data-reference") == "true";
        assert!(color.starts_with('#') && color.len() == 7 && !marker.is_empty(), "{file}: {:?}", e.attrs);
        if reference {
            assert_eq!(color, "#000000", "{file}: reference {model} not black");
        }
        let prev = styles.insert((model.into(), reference), (color.into(), marker.into()));
        assert!(prev.is_none_or(|p| p == (color.to_string(), marker.to_string())), "{file}: {model} in two styles");
        let owner = by_look.entry((color.into(), marker.into())).or_insert_with(|| model.into());
        assert_eq!(owner, model, "{file}: {owner} and {model} look alike ({color}, {marker})");
        let panel = e.within("panel").map(translate).unwrap_or_default();
        *in_panel.entry((format!("{panel:?}"), format!("{model}{reference}"))).or_default() += 1;
    }
    for ((panel, model), n) in &in_panel {
        assert_eq!(*n, 1, "{file}: {model} drawn {n} times in the panel at {panel}");
    }
    let drawn = elements.iter().filter(|e| {
        e.within("series").is_some() && matches!(e.name.as_str(), "polyline" | "circle" | "polygon" | "path")
    });
    for e in drawn {
        let declared = e.within("series").unwrap().get("data-color").unwrap();
        assert_eq!(e.attr("stroke"), declared, "{file}: a <{}> of {:?}", e.name, e.within("series"));
    }

    // Tick labels: apart along their axis, in every panel and colour bar; never "-0".
    let mut ticks: BTreeMap<(String, &str), Vec<(f64, &Element)>> = BTreeMap::new();
    for e in elements.iter().filter(|e| e.name == "text" && e.class().starts_with("tick")) {
        let t = e.text.trim();
        assert!(!t.is_empty(), "{file}: empty tick label");
        assert!(!(t.starts_with('-') && t[1..].chars().all(|c| c == '0' || c == '.')), "{file}: tick {t:?}");
        let owner = e.within("panel").or_else(|| e.within("colorbar")).map(translate).unwrap_or_default();
        let along = if e.class() == "tick x" { e.num("x") } else { e.num("y") };
        ticks.entry((format!("{owner:?}"), e.class())).or_default().push((along, e));
    }
    for ((owner, class), mut labels) in ticks {
        assert!(labels.len() >= 2, "{file}: {class} in {owner}: {} label(s)", labels.len());
        labels.sort_by(|a, b| a.0.total_cmp(&b.0));
        for w in labels.windows(2) {
            let ((a, ea), (b, eb)) = (w[0], w[1]);
            let needed = if class == "tick x" {
                0.5 * (width(&ea.text, ea.num("font-size")) + width(&eb.text, eb.num("font-size")))
            } else {
                ea.num("font-size")
            };
            assert!(
                b - a >= needed,
                "{file}: {class} labels {:?} and {:?} overlap ({:.1} px apart)",
                ea.text,
                eb.text,
                b - a
            );
        }
    }

    // Axis titles: a name with a unit, never a scene key.
    for e in elements.iter().filter(|e| e.class().starts_with("axis-title")) {
        let t = &e.text;
        assert!(t.ends_with(']') && t.contains(" ["), "{file}: axis title {t:?} without a unit");
        let key =
            t.as_bytes().windows(3).any(|w| w[0].is_ascii_alphabetic() && w[1] == b'.' && w[2].is_ascii_alphabetic());
        assert!(!key, "{file}: axis title {t:?} looks like a scene key");
    }
    assert_eq!(elements.iter().filter(|e| e.class().starts_with("axis-title")).count(), 2, "{file}: axis titles");

    // The legend (line charts) or the colour bar and key (patch maps) right of every plot area.
    let panels: Vec<f64> =
        elements.iter().filter(|e| e.class() == "panel").map(|e| translate(&e.attrs).0 + e.num("data-width")).collect();
    assert!(!panels.is_empty(), "{file}: no plot area");
    let right = panels.iter().fold(0.0f64, |m, x| m.max(*x));
    let side =
        elements.iter().find(|e| e.class() == "legend" || e.class() == "colorbar").expect("a legend or colour bar");
    assert!(translate(&side.attrs).0 >= right, "{file}: {} inside the plot area (x {right})", side.class());
    if side.class() == "colorbar" {
        let texts: Vec<&str> = elements.iter().filter(|e| e.name == "text").map(|e| e.text.as_str()).collect();
        for needed in ["p [MPa]", "adhesion", "slip"] {
            assert!(texts.contains(&needed), "{file}: no {needed:?} in the colour bar and key");
        }
    } else {
        let entries: Vec<(String, bool)> = elements
            .iter()
            .filter(|e| e.class() == "legend-entry")
            .map(|e| (e.attr("data-model").to_string(), e.attr("data-reference") == "true"))
            .collect();
        for (model, reference) in styles.keys() {
            assert!(entries.contains(&(model.clone(), *reference)), "{file}: {model} not in the legend");
        }
    }
    let colors: Vec<String> = styles.values().map(|(c, _)| c.clone()).collect();
    render(file, svg, &colors);
    styles
}

#[test]
fn every_figure_of_the_report_passes_the_checks() {
    use creepbench::comparison::references::References;
    use creepbench::suite::results;
    let golden = root().join("golden");
    let scenes: Vec<_> =
        results::scene_names(&golden).iter().map(|n| results::read_scene(&golden, n).unwrap()).collect();
    assert!(scenes.len() >= 200, "{} golden scenes", scenes.len());
    let refs = References::load(&root().join("reference")).unwrap();
    let out = tempdir("figures_report");
    let md = creepbench::commands::build_report(&scenes, &refs, &out, None, &[], &[], Vec::new()).unwrap();
    let markdown = std::fs::read_to_string(md).unwrap();

    let mut model_styles: BTreeMap<(String, bool), (String, String, String)> = BTreeMap::new();
    let mut files: Vec<_> = std::fs::read_dir(out.join("figures"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    files.sort();
    let mut kinds = BTreeMap::new();
    for path in &files {
        let file = path.file_name().unwrap().to_string_lossy().to_string();
        assert!(markdown.contains(&format!("figures/{file}")), "{file} not in the report");
        let svg = std::fs::read_to_string(path).unwrap();
        for (key, (color, marker)) in check(&file, &svg) {
            let (c, m, first) =
                model_styles.entry(key.clone()).or_insert((color.clone(), marker.clone(), file.clone()));
            assert_eq!((&*c, &*m), (&color, &marker), "{key:?}: {color} {marker} in {file}, {c} {m} in {first}");
        }
        let kind = if file.contains("_patch_") {
            "patch"
        } else if file.starts_with("study_") {
            "study"
        } else {
            "line"
        };
        *kinds.entry(kind).or_insert(0) += 1;
    }
    // Every figure the report names is there.
    for name in markdown.split("(figures/").skip(1).map(|s| s.split(')').next().unwrap()) {
        assert!(out.join("figures").join(name).exists(), "{name} named in the report, not written");
    }
    assert!(files.len() >= 250, "{} figures", files.len());
    assert!(
        kinds.get("patch").copied().unwrap_or(0) >= 10 && kinds.get("study").copied().unwrap_or(0) >= 10,
        "{kinds:?}"
    );
    // Every built-in model the golden scenes ran and both reference sets were drawn (and so
    // checked above). (`kpec` and `analyn` have no golden scene: the wheel–rail report test draws every model.)
    let ran = |m: &str| scenes.iter().any(|s| s.histories.contains_key(m));
    for m in creepbench::solvers::builtin_names().into_iter().filter(|m| ran(m)) {
        assert!(model_styles.contains_key(&(m.to_string(), false)), "{m} in no figure");
    }
    for r in ["CONTACT", "thesis"] {
        assert!(model_styles.contains_key(&(r.to_string(), true)), "{r} in no figure");
    }
}

/// A user's own model beside the built-in ones (a suite of one's own), and the cost plot's axes:
/// the same checks, the user's model in a style of its own, the built-in ones as everywhere.
#[test]
fn a_users_model_and_log_axes_pass_the_checks() {
    let curve = |k: f64| (1..=40).map(|i| (f64::from(i) * 1e-3, 0.1 * k + 0.01 * f64::from(i).sqrt())).collect();
    let series = vec![
        Series::model("uba", curve(1.0)),
        Series::model("my_model", curve(2.0)),
        Series::model("fastsim", curve(3.0)),
        Series::reference("CONTACT", curve(1.5).into_iter().step_by(4).collect()),
    ];
    let svg = line_chart("own suite", &Axis::linear("t [s]"), &Axis::linear("f_x / F_N [–]"), &series);
    let styles = check("own suite", &svg);
    assert_eq!(styles[&("uba".to_string(), false)], ("#CC6677".to_string(), "square".to_string()));
    assert_ne!(styles[&("my_model".to_string(), false)].0, styles[&("uba".to_string(), false)].0);

    let cost: Vec<Series> = ["contact", "uba", "fastsim"]
        .iter()
        .enumerate()
        .map(|(k, m)| {
            Series::model(
                *m,
                [484.0, 1936.0, 7744.0, 30976.0].iter().map(|n| (*n, 1e-7 * 10f64.powi(k as i32) * n)).collect(),
            )
        })
        .collect();
    let svg = line_chart("cost", &Axis::log("grid elements [–]"), &Axis::log("time per step [s]"), &cost);
    check("cost", &svg);
    let labels: Vec<&str> = svg
        .split(r#"class="tick y""#)
        .skip(1)
        .map(|s| s.split('>').nth(1).unwrap().split('<').next().unwrap())
        .collect();
    assert_eq!(labels, ["1e-5", "1e-4", "0.001", "0.01", "0.1", "1"], "decades on the time axis");
}
