//! The cross-scene results table: one row per scene, solver and quantity (metrics, and the worst
//! |f − f_CONTACT| where a reference exists), written as CSV and, with the optional `polars`
//! feature, as a polars DataFrame saved to Parquet for users who analyse in Python.

use crate::comparison::compare::Finding;
use crate::suite::results::StoredScene;
use std::path::Path;

/// One row of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct TableRow {
    pub scene: String,
    pub solver: String,
    pub quantity: String,
    /// Sweep point for per-point metrics, else None.
    pub step: Option<usize>,
    pub value: f64,
}

/// The rows, sorted by scene, solver, quantity and step.
pub fn rows(scenes: &[StoredScene], findings: &[Finding]) -> Vec<TableRow> {
    let mut out = Vec::new();
    for s in scenes {
        for ((solver, metric, step), v) in &s.metrics {
            out.push(TableRow {
                scene: s.name.clone(),
                solver: solver.clone(),
                quantity: metric.clone(),
                step: *step,
                value: *v,
            });
        }
    }
    for f in findings.iter().filter(|f| f.against.is_contact() && f.quantity == "fx_over_fn") {
        out.push(TableRow {
            scene: f.scene.clone(),
            solver: f.solver.clone(),
            quantity: "max_abs_error_vs_contact".into(),
            step: f.step,
            value: f.diff,
        });
    }
    out.sort_by(|a, b| (&a.scene, &a.solver, &a.quantity, a.step).cmp(&(&b.scene, &b.solver, &b.quantity, b.step)));
    out
}

/// The results table's file name in the report folder.
pub const FILE: &str = "results.csv";

/// Write `dir/results.csv` whole (and `dir/results.parquet` with the `polars` feature).
pub fn write(dir: &Path, rows: &[TableRow]) -> std::io::Result<()> {
    let mut s = String::from("scene,solver,quantity,step,value\n");
    for r in rows {
        s.push_str(&format!(
            "{},{},{},{},{}\n",
            r.scene,
            r.solver,
            r.quantity,
            r.step.map(|k| k.to_string()).unwrap_or_default(),
            r.value
        ));
    }
    crate::safety::whole::write(&dir.join(FILE), s.as_bytes())?;
    #[cfg(feature = "polars")]
    {
        let mut df = dataframe(rows).map_err(std::io::Error::other)?;
        let file = std::fs::File::create(dir.join("results.parquet"))?;
        polars::prelude::ParquetWriter::new(file).finish(&mut df).map_err(std::io::Error::other)?;
    }
    Ok(())
}

/// The table as a polars DataFrame (columns scene, solver, quantity, step, value).
#[cfg(feature = "polars")]
pub fn dataframe(rows: &[TableRow]) -> polars::prelude::PolarsResult<polars::prelude::DataFrame> {
    use polars::prelude::*;
    df!(
        "scene" => rows.iter().map(|r| r.scene.as_str()).collect::<Vec<_>>(),
        "solver" => rows.iter().map(|r| r.solver.as_str()).collect::<Vec<_>>(),
        "quantity" => rows.iter().map(|r| r.quantity.as_str()).collect::<Vec<_>>(),
        "step" => rows.iter().map(|r| r.step.map(|k| k as u64)).collect::<Vec<_>>(),
        "value" => rows.iter().map(|r| r.value).collect::<Vec<_>>()
    )
}
