//! The resolved scene as one typed record: written as scene.json by `simulate`, `run` and
//! `bless` (docs/scene-format.md: at least a_mm, b_mm, p0_mpa, c11, c22, c23, dx_mm, dy_mm, dt_s,
//! n_steps and the solvers that ran), read back by the harness and by external models.

use super::params::ParamEntries;
use super::{DeclaredLoading, LoadingKind, Problem, Sample, Stepping};
use crate::error::InputError;
use crate::scene::report::ReportGroup;
use crate::scene::{ContactSolverOptions, InitKind, ModelOptions, NormalOptions};
use serde::{Deserialize, Serialize};

/// scene.json.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResolvedScene {
    pub name: String,
    pub solvers: Vec<String>,
    pub kind: LoadingKind,
    pub a_mm: f64,
    pub b_mm: f64,
    pub fn_n: f64,
    /// The scene's nominal μ (`contact.mu`); a table may vary μ per step (`history`).
    pub mu: f64,
    /// A falling or temperature friction law (`[friction]`; absent: Coulomb with `mu`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<crate::physics::FrictionLaw>,
    /// The friction memory (absent: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub memory: Option<crate::physics::Memory>,
    /// Coulomb's μ per grid row, the first at the lowest y (`[friction] mu_rows`; absent: one μ).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu_rows: Option<Vec<f64>>,
    /// Hertz peak pressure 3FN/(2πab) [MPa].
    pub p0_mpa: f64,
    /// Peak of the simplified models' pressure (`model.pressure`) [MPa].
    pub p_model_peak_mpa: f64,
    pub g_mpa: f64,
    pub e_mpa: f64,
    pub poisson: f64,
    /// Kalker's difference parameter K of dissimilar bodies (`[material] g1_mpa` … `poisson2`);
    /// absent for quasi-identical bodies (K = 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kalker_k: Option<f64>,
    /// The interface layer between the bodies (`[material] layer_g_mpa`, `layer_thickness_mm`;
    /// absent: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub layer: Option<crate::physics::material::Layer>,
    /// Viscoelastic bodies (`[material] visco_ratio`, `visco_time_s`; absent: elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub visco: Option<crate::physics::material::Visco>,
    /// Both bodies' thermal constants (`[material] bulk1_c` …; absent: no surface temperatures).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat: Option<[crate::physics::temperature::Thermal; 2]>,
    pub c11: f64,
    pub c22: f64,
    pub c23: f64,
    /// Kalker's spin–moment coefficient (absent in results written before it was added).
    #[serde(default)]
    pub c33: f64,
    pub l1_mm3_n: f64,
    pub l2_mm3_n: f64,
    pub l3_mm3_n: f64,
    pub mx: usize,
    pub my: usize,
    pub dx_mm: f64,
    pub dy_mm: f64,
    /// The grid's extent in nominal semi-axes (`[grid] scale`; 1 in folders written before it).
    #[serde(default = "one")]
    pub grid_scale: f64,
    pub v_mm_s: f64,
    pub courant: f64,
    pub dq_mm: f64,
    pub dt_s: f64,
    /// The rolling direction [deg] where it is not 0 (`[rolling] chi_deg`; absent along +x).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub chi_deg: Option<f64>,
    pub n_steps: usize,
    pub freq_hz: Option<f64>,
    /// A sweep's direction in (cx, cy, cs): creepage = constants + t·direction (sweep kind only;
    /// a sweep written before it existed is read as the cx sweep [1, 0, 0]).
    #[serde(default)]
    pub sweep_direction: Option<[f64; 3]>,
    pub init: InitKind,
    pub model: ModelRecord,
    pub contact_solver: ContactSolverOptions,
    /// The exact solver's normal problem (`[normal]`; absent: solved).
    #[serde(default, skip_serializing_if = "NormalOptions::is_default")]
    pub normal: NormalOptions,
    pub metrics: Vec<String>,
    /// (metric, why it was left out).
    pub skipped_metrics: Vec<(String, String)>,
    pub warnings: Vec<String>,
    /// The contact geometry's kind (`hertz`; absent in result folders written before it existed).
    #[serde(default = "hertz")]
    pub geometry: String,
    /// A geometry given per element: the grid's edges in CONTACT's coordinates, `[[x0, x1],
    /// [y0, y1]]`, and the undeformed distance [mm] per element in CONTACT's order (index
    /// `(iy − 1) mx + (ix − 1)`, ix along CONTACT's x), so that an external model sees the shape.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid_edges_mm: Option<[[f64; 2]; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub undeformed_distance_mm: Option<Vec<f64>>,
    /// The name of the folder of the scene file: its suite (`thesis`, `stability`, …), so that
    /// `check` knows which blessed scenes a suite must produce.
    #[serde(default)]
    pub suite: String,
    /// The studies the scene is a point of (absent for a scene of its own).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub studies: Vec<crate::scene::study::StudyPoint>,
    /// The CONTACT deck and first and last case the scene was imported from (absent for a
    /// scene of this project's own).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub origin: Option<crate::scene::Origin>,
    /// Where the report shows the scene (`[report] group`; absent: `other`). Not a result: a
    /// baseline's scene.json is compared without it.
    #[serde(default, skip_serializing_if = "ReportGroup::is_default")]
    pub report_group: ReportGroup,
    /// The subsurface points of `[stress]` (absent: none asked for).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress: Option<crate::scene::stress::StressPoints>,
    /// The loading as the scene declared it; its rows are [`ResolvedScene::loading_rows`]
    /// (absent only in result folders written before it, which list `history`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub loading: Option<DeclaredLoading>,
    /// The loading at every row, as result folders written before `loading` listed it: read,
    /// never written.
    #[serde(default, skip_serializing, rename = "history")]
    pub legacy_history: Vec<Sample>,
}

/// scene.json's `model`: the shared options, then each model's own parameters in registry order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModelRecord {
    #[serde(flatten)]
    pub options: ModelOptions,
    #[serde(flatten)]
    pub params: ParamEntries,
}

fn hertz() -> String {
    "hertz".into()
}

fn one() -> f64 {
    1.0
}

impl ResolvedScene {
    /// The record of `p`, which it consumes (its sampled loading is dropped: the record holds
    /// the declaration).
    pub fn of_owned(p: Problem, solvers_ran: &[String]) -> ResolvedScene {
        Self::of(&p, solvers_ran)
    }

    /// The loading at every row (step 0 = the initial state at t = 0, when the scene has one):
    /// the declared loading sampled as the run sampled it ([`DeclaredLoading::sample`]), or a
    /// folder's `history` written before the declaration was recorded.
    pub fn loading_rows(&self) -> Result<Vec<Sample>, InputError> {
        let Some(declared) = &self.loading else {
            return Ok(self.legacy_history.clone());
        };
        let at = Stepping {
            init: self.init,
            dt_s: self.dt_s,
            v_mm_s: self.v_mm_s,
            dx_mm: self.dx_mm,
            file: std::path::Path::new("scene.json"),
        };
        Ok(declared.sample(at)?.all_rows())
    }

    /// The record of `p`, naming the solvers that ran.
    pub fn of(p: &Problem, solvers_ran: &[String]) -> ResolvedScene {
        let h = p.hertz();
        let flex = p.flexibilities();
        ResolvedScene {
            name: p.name.clone(),
            solvers: solvers_ran.to_vec(),
            kind: p.loading.kind,
            a_mm: h.a_mm,
            b_mm: h.b_mm,
            fn_n: h.fn_n,
            mu: p.nominal.mu,
            friction: (!matches!(p.friction, crate::physics::FrictionLaw::Coulomb { .. })).then_some(p.friction),
            memory: p.memory.is_active().then_some(p.memory),
            mu_rows: p.friction_rows.as_ref().map(|r| r.rows().to_vec()),
            p0_mpa: h.p0_mpa(),
            p_model_peak_mpa: p.model.pressure.peak_mpa(h.fn_n, h.a_mm, h.b_mm),
            g_mpa: p.material.g_mpa,
            e_mpa: p.material.e_mpa,
            poisson: p.material.poisson,
            kalker_k: p.material.coupled().then_some(p.material.k),
            layer: p.material.layer,
            visco: p.material.visco,
            heat: p.material.heat,
            c11: p.coefficients.c11,
            c22: p.coefficients.c22,
            c23: p.coefficients.c23,
            c33: p.coefficients.c33,
            l1_mm3_n: flex.l1_mm3_n,
            l2_mm3_n: flex.l2_mm3_n,
            l3_mm3_n: flex.l3_mm3_n,
            mx: p.grid.mx,
            my: p.grid.my,
            dx_mm: p.grid.dx_mm,
            dy_mm: p.grid.dy_mm,
            grid_scale: p.grid_scale,
            v_mm_s: p.rolling.v_mm_s,
            courant: p.rolling.courant,
            dq_mm: p.rolling.dq_mm,
            dt_s: p.rolling.dt_s,
            chi_deg: (p.rolling.chi_deg != 0.0).then_some(p.rolling.chi_deg),
            n_steps: p.loading.samples.len(),
            freq_hz: p.loading.freq_hz,
            sweep_direction: p.loading.sweep_direction,
            init: p.loading.init,
            model: ModelRecord { options: p.model, params: p.model_params.scene_json() },
            contact_solver: p.contact_solver,
            normal: p.normal,
            metrics: p.metrics.clone(),
            skipped_metrics: p.skipped_metrics.clone(),
            warnings: p.warnings.clone(),
            geometry: p.geometry.kind().to_string(),
            grid_edges_mm: p.grid_edges.map(|(x, y)| [x, y]),
            undeformed_distance_mm: (!p.geometry.elliptic()).then(|| {
                let g = &p.grid;
                let h = p.geometry.undeformed_distance_mm(g, h.fn_n, &p.material);
                (0..g.len()).map(|k| h[g.index(g.mx - 1 - k % g.mx, k / g.mx)]).collect()
            }),
            suite: p.scene_dir.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default(),
            studies: p.studies.clone(),
            origin: p.origin.clone(),
            report_group: p.report_group,
            stress: p.stress.clone(),
            loading: Some(p.declared.clone()),
            legacy_history: Vec::new(),
        }
    }

    /// scene.json text (pretty, shortest round-trip numbers, newline-terminated).
    pub fn to_json(&self) -> String {
        let mut out = Vec::new();
        self.write_json(&mut out).expect("writing into memory does not fail");
        String::from_utf8(out).expect("serde_json writes UTF-8")
    }

    /// The scene.json text of [`ResolvedScene::to_json`], written into `out` as it is produced.
    pub fn write_json(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        serde_json::to_writer_pretty(&mut *out, self)?;
        out.write_all(b"\n")
    }

    /// Parse scene.json text (a sweep without `sweep_direction` is the cx sweep it was written as).
    pub fn from_json(text: &str) -> Result<ResolvedScene, serde_json::Error> {
        let mut scene: ResolvedScene = serde_json::from_str(text)?;
        if scene.kind == LoadingKind::Sweep && scene.sweep_direction.is_none() {
            scene.sweep_direction = Some([1.0, 0.0, 0.0]);
        }
        Ok(scene)
    }

    /// Sine period [s], if the scene is a sine.
    pub fn period_s(&self) -> Option<f64> {
        self.freq_hz.map(|f| 1.0 / f)
    }
}
