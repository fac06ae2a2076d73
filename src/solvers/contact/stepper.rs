//! The exact-theory solver as a stepper: the influence kernels once per grid, the normal problem
//! once per load, then one tangential solve per sample (steady: [`TangentialSolver::steady`];
//! transient: [`TangentialSolver::transient_step`] from the last two steps' tractions).

use super::coupled::{self, Couplings, Kind};
use super::direction;
use super::force;
use super::hardening::{Hardening, HardeningOutcome};
use super::heat;
use super::influence::{Basis, Kernel};
use super::mirror;
use super::normal::{NormalParams, NormalSolver};
use super::restart::{contact_restart, SteadyRestart, SteadyStart};
use super::tangential::{StepResult, TangentialParams, TangentialSolver};
use super::tempdep::{TempDep, TempDepOptions};
use super::veldep::{step_start, Motion as LawStep, VelDep, VelDepOptions, VelDepOutcome};
use super::ContactError;
use crate::error::InputError;
use crate::physics::geometry::element::equivalent_ellipse;
use crate::physics::halfspace::visco::Relaxation;
use crate::physics::{moment_sum, FrictionLaw, LinearTheory, NormalPressure};
use crate::problem::{Problem, Sample};
use crate::scene::Motion;
use crate::solvers::stepper::{FieldView, Step, Stepper};
use crate::solvers::style::{muted, Dash, Marker};
use crate::solvers::{ModelDef, SolveError};

/// The exact model's name in scenes and of its `<name>.csv`.
pub const NAME: &str = "contact";

/// Kalker's exact theory for quasi-identical half-spaces (CONTACT-style).
pub const MODEL: ModelDef = ModelDef {
    name: NAME,
    summary: "Kalker's exact theory on the same grid (CONTACT-style: half-space influence coefficients, normal problem, transient rolling with Coulomb friction)",
    extra_columns: &["n_adhesion", "n_slip", "iterations", "residual", "pn_max_mpa"],
    iterative: true,
    prescribed_forces: true,
    shifts: true,
    normal_rows: true,
    own_normal: None,
    check,
    cost_per_row,
    params: None,
    build,
    style: muted(0, Dash::Solid, Marker::Circle),
};

/// Wall time per unit of [`cost_per_row`] [s], the 88×88 transient step of the `contact_step`
/// bench divided by its N log N: turns the cost into the estimate `[limits]` bounds.
const SECONDS_PER_COST: f64 = 1.3e-7;

/// A run estimated to take longer than `[limits] max_estimated_s` is refused before it starts.
fn check(p: &Problem) -> Result<(), InputError> {
    check_kinetic_floor(p)?;
    check_heat(p)?;
    check_coupled(p)?;
    if p.friction.is_falling() && p.loading.rows().any(|s| s.courant.is_some()) {
        return Err(InputError::new(
            "creepage.file column courant",
            "a rolling distance per row with a falling [friction] law",
            "a courant column with Coulomb friction, or [rolling] courant with a falling law (its memory and slip velocity take one rolling distance)",
        ));
    }
    if let Some(what) = p.loading.normal_rows().filter(|_| !p.normal.is_default()) {
        return Err(InputError::new(
            "normal.pressure",
            format!("{:?} with {what}", p.normal.pressure.name()),
            "an imposed pressure (Hertz's ellipse at the row's FN) only on rows that give FN: leave out the table's pen_mm and b1_per_mm..b6_mm, or solve the normal problem (\"solved\")",
        ));
    }
    if p.loading.rows().any(|s| s.courant.is_some()) && p.loading.rows().any(|s| s.chi_deg_or(p.rolling.chi_deg) != 0.0)
    {
        return Err(InputError::new(
            "creepage.file column courant",
            "a rolling distance per row with a rolling direction other than +x",
            "a courant column with CHI = 0 only (rolling.chi_deg and the table's chi_deg 0), or one rolling distance ([rolling] courant) with another direction",
        ));
    }
    let chi_of = |s: &Sample| s.chi_deg_or(p.rolling.chi_deg);
    let turned = p.loading.rows().map(chi_of).find(|&c| c != 0.0);
    if let Some(chi_deg) = turned.filter(|_| p.rolling.motion == Motion::Shift || p.friction.is_falling()) {
        return Err(InputError::new(
            "rolling.chi_deg",
            chi_deg,
            "0 with rolling.motion = \"shift\" or a falling [friction] law (the exact solver rolls along another direction than +x with Coulomb friction only)",
        ));
    }
    if p.extra_slip.is_some() && (p.rolling.motion == Motion::Shift || turned.is_some()) {
        return Err(InputError::new(
            "creepage.extra_slip",
            "an extra rigid slip per element with shifts or a rolling direction other than +x",
            "an extra slip in rolling along +x only (rolling.motion = \"rolling\", chi_deg 0 in every row)",
        ));
    }
    let steady: Vec<&Sample> = match p.loading.steady_start() {
        Some(start) => vec![start],
        None if !p.loading.is_transient() => p.loading.rows().collect(),
        None => Vec::new(),
    };
    let mirrored = mirrored(p);
    if let Some(chi_deg) = steady.iter().map(|&s| chi_of(s)).find(|&c| c != 0.0 && !(c == 180.0 && mirrored)) {
        return Err(InputError::new(
            "rolling.chi_deg",
            chi_deg,
            "0 or 180 in steady rolling (a sweep or a steady start, 0 where the table's chi_deg turns the history; CONTACT's steady solver rolls along +x or -x, m_sdis.f90 check_roll_stepsize), any angle in transient rolling",
        ));
    }
    let entering = p.rolling.dq_mm > p.grid.dx_mm;
    if !mirrored && entering && p.loading.rows().any(|s| chi_of(s) == 180.0) {
        return Err(InputError::new(
            "creepage.file column chi_deg",
            180,
            "another direction with dq > dx (rolling.courant > 1) where the history turns: CONTACT's leading-edge correction follows -x at CHI = 180 only when the whole history rolls so",
        ));
    }
    let estimated_s = p.loading.rows().count() as f64 * cost_per_row(p) * SECONDS_PER_COST;
    if estimated_s <= p.limits.max_estimated_s {
        return Ok(());
    }
    Err(InputError::new(
        "limits.max_estimated_s",
        p.limits.max_estimated_s,
        format!("a limit above the exact-theory solver's estimated {estimated_s:.0} s for {} rows on {}x{} elements (raise it to run this scene)", p.loading.rows().count(), p.grid.mx, p.grid.my),
    ))
}

/// Surface temperatures ([`heat`]) are computed in steady rolling (CONTACT's `calc_temp` stops
/// at T ≠ 3) on elastic bodies or an elastic layer (a plastic layer's heat, BETAPL, is not carried).
fn check_heat(p: &Problem) -> Result<(), InputError> {
    if p.material.heat.is_none() {
        return Ok(());
    }
    let allowed = "surface temperatures in steady rolling (kind = \"sweep\", rolling.motion = \"rolling\") on elastic bodies or an elastic layer (CONTACT's H = 3 with T = 3; the heat of a plastic layer, BETAPL, is not carried)";
    if p.loading.is_transient() || p.rolling.motion == Motion::Shift {
        let what = if p.rolling.motion == Motion::Shift { "shifts" } else { "transient rolling" };
        return Err(InputError::new("material.bulk1_c", format!("surface temperatures with {what}"), allowed));
    }
    if p.material.layer.is_some_and(|l| l.yield_mpa.is_some()) {
        return Err(InputError::new("material.bulk1_c", "surface temperatures with a plastic layer", allowed));
    }
    Ok(())
}

/// Dissimilar bodies (K ≠ 0, [`coupled`]): the outer iteration is written for Coulomb's one μ, a
/// solved normal problem, uniform tractions, one rolling direction and distance.
fn check_coupled(p: &Problem) -> Result<(), InputError> {
    if !p.material.coupled() {
        return Ok(());
    }
    let k = p.material.k;
    let refuse = |field: &str, what: &str| {
        Err(InputError::new(
            field,
            format!("{what} with dissimilar bodies (K = {k})"),
            "dissimilar bodies with Coulomb's one mu, a solved normal problem, influence = \"constant\", one rolling direction and distance (the outer iteration between the normal and tangential problems is written for these)",
        ))
    };
    if p.friction.is_falling() || p.friction.temperature().is_some() {
        return refuse("friction.law", "a falling or temperature friction law");
    }
    if p.friction_rows.is_some() {
        return refuse("friction.mu_rows", "a friction per grid row");
    }
    if !p.normal.is_default() {
        return refuse("normal.pressure", "an imposed pressure");
    }
    if p.contact_solver.influence != Basis::Constant {
        return refuse("contact_solver.influence", "bilinear influence functions");
    }
    if p.loading.rows().any(|s| s.courant.is_some()) {
        return refuse("creepage.file column courant", "a rolling distance per row");
    }
    if p.loading.rows().any(|s| s.chi_deg.is_some()) {
        return refuse("creepage.file column chi_deg", "a rolling direction per row");
    }
    Ok(())
}

/// A falling law needs FKIN > 0 here: the traction bound μ(s)·pn must be positive on the whole
/// contact ([`TangentialSolver::set_bound`]). μ_s(s) ≥ FKIN, and the memory's μ lies between μ_prev
/// and μ_s (`physics::Memory::update`), so FKIN > 0 keeps it positive; with FKIN = 0 the bound
/// reaches 0: the linear law at s ≥ 2·SABSH (`m_friclaw.f90` lines 422-426), the exponential and
/// rational laws where their terms underflow.
fn check_kinetic_floor(p: &Problem) -> Result<(), InputError> {
    let fkin = match &p.friction {
        // FREF > 0 and FREF + DFHEAT > 0 (the scene's reader): μ(T) lies between them.
        FrictionLaw::Coulomb { .. } | FrictionLaw::Temperature(_) => return Ok(()),
        FrictionLaw::Linear(t) | FrictionLaw::Rational(t) | FrictionLaw::Exponential(t) => t.fkin,
    };
    if fkin > 0.0 {
        return Ok(());
    }
    Err(InputError::new(
        "friction.fkin",
        fkin,
        "a kinetic coefficient > 0 when the scene runs contact (the exact solver's traction bound mu(s) p must stay positive on the contact; with fkin = 0 the law falls to mu = 0: the linear law at s >= 2 sabsh1_mm_s, the others where their terms underflow); fastsim, uba, relaxation and polach take fkin = 0",
    ))
}

/// Whether the solver works in the frame mirrored about x = 0 ([`mirror`]): the whole history
/// rolls along -x (`[rolling] chi_deg = 180`, no table column `chi_deg` turning it).
fn mirrored(p: &Problem) -> bool {
    p.rolling.backward() && p.loading.rows().all(|s| s.chi_deg.is_none())
}

/// The tangential solver rolling along CHI = `chi_deg` (grid coordinates; 0: the solver's own
/// direction, bit for bit).
fn tangential_at(
    p: &Problem,
    k0: &Kernel,
    chi_deg: f64,
    x: &[f64],
    y: &[f64],
) -> Result<TangentialSolver, ContactError> {
    let (g, m, basis) = (&p.grid, &p.material, p.contact_solver.influence);
    let (dq, flx) = (p.rolling.dq_mm, m.layer_flexibility_mm_per_mpa());
    let held = |offset: [f64; 2]| if layer_in_place(p) { [0.0, 0.0] } else { offset };
    if chi_deg == 0.0 {
        let ks = kernel_along_x(p, dq)?.with_layer(flx, held([dq, 0.0]))?;
        return TangentialSolver::new(k0, &ks, x, y);
    }
    let towards = direction::towards(chi_deg);
    let ks = Kernel::rolling(g.mx, g.my, (g.dx_mm, g.dy_mm), (m.g_mpa, m.poisson), (dq, towards), basis)?
        .with_layer(flx, held([dq * towards[0], dq * towards[1]]))?;
    TangentialSolver::rolling_towards(k0, &ks, towards, x, y)
}

/// Whether the rolling solver takes an interface layer's previous displacement at the element's
/// own index on the moved grid: in transient rolling with a layer's thickness, as CONTACT does
/// (`stang_rhs` in `m_stang.f90` forms the previous displacement from the previous tractions with
/// the shifted coefficients CV, whose layer term, `gf3_aijpj` in `m_aijpj.f90`, adds FLX times the
/// previous traction of the element itself); steady rolling carries it with the material
/// (its own solver, [`Contact::steady_dx`], as CONTACT's SteadyGS differences it along the rows).
fn layer_in_place(p: &Problem) -> bool {
    let rolls = p.rolling.motion == Motion::Rolling && p.loading.is_transient();
    rolls && p.material.layer_flexibility_mm_per_mpa() > 0.0
}

/// The kernel of the grid with the field point shifted by `shift_mm` along x: elastic, or of
/// viscoelastic bodies (`[material] visco_*`, CONTACT's M = 1) with the relaxation distance
/// V·τ at the scene's speed ([`Kernel::viscoelastic`]).
fn kernel_along_x(p: &Problem, shift_mm: f64) -> Result<Kernel, ContactError> {
    let (g, m, basis) = (&p.grid, &p.material, p.contact_solver.influence);
    let (size, elastic) = ((g.dx_mm, g.dy_mm), (m.g_mpa, m.poisson));
    match m.visco {
        None => Kernel::with_basis(g.mx, g.my, size, elastic, shift_mm, basis),
        Some(v) => {
            let relax = Relaxation { ratio: v.ratio, distance_mm: v.time_s * p.rolling.v_mm_s };
            Kernel::viscoelastic(g.mx, g.my, size, elastic, shift_mm, (basis, relax))
        }
    }
}

/// About `N log N` per transient step for `N` elements (FFT products); a steady point about 3 steps.
fn cost_per_row(p: &Problem) -> f64 {
    let n = p.grid.len() as f64;
    let per_row = if p.loading.is_transient() { 1.0 } else { 3.0 };
    per_row * n * n.max(2.0).ln()
}

/// Mindlin's tangential stiffness of a stuck circle of radius √(ab), both bodies of the same
/// material: F/δ = 4 G a / (2 − ν) (Johnson 1985, eq. 7.29 with Q ≪ μP) [N/mm]; the start
/// of the prescribed-force iteration under shifts.
fn mindlin_stiffness_n_mm(p: &Problem, ab_mm2: f64) -> f64 {
    4.0 * p.material.g_mpa * ab_mm2.sqrt() / (2.0 - p.material.poisson)
}

/// Failures of the exact-theory solver.
#[derive(Debug, thiserror::Error)]
pub enum ContactRunError {
    #[error("influence kernels: {0}")]
    Kernel(#[source] ContactError),
    #[error("normal problem at FN = {fn_n} N: {source}")]
    Normal { fn_n: f64, source: ContactError },
    #[error("normal problem at FN = {fn_n} N did not converge in {iterations} iterations (residual {residual:.2e})")]
    NormalNotConverged { fn_n: f64, iterations: usize, residual: f64 },
    #[error("normal problem at the approach {pen_mm} mm: {source}")]
    Approach { pen_mm: f64, source: ContactError },
    #[error("normal problem at the approach {pen_mm} mm did not converge in {iterations} iterations (residual {residual:.2e})")]
    ApproachNotConverged { pen_mm: f64, iterations: usize, residual: f64 },
    #[error("no element of the {mx}x{my} grid carries load at FN = {fn_n} N")]
    NoContact { mx: usize, my: usize, fn_n: f64 },
    #[error("tangential problem at FN = {fn_n} N: {source}")]
    Setup { fn_n: f64, source: ContactError },
    #[error("step {step}: {source}")]
    Step { step: usize, source: ContactError },
}

/// The normal solution at one load.
struct Loaded {
    /// The sample's (FN, approach, undeformed distance, pressure kind) it was solved for.
    key: (f64, Option<f64>, Option<[f64; 6]>, NormalPressure),
    /// The total normal force [N]: the sample's, or found for its approach.
    fn_n: f64,
    pn: Vec<f64>,
    /// With μ per grid row, the tangential solvers' bound pressure p μ_j/μ_max
    /// ([`crate::physics::RowFriction::bound_pressure`]), with a layer's yield limit capped at
    /// τ_c0/μ ([`crate::physics::material::Layer::capped_pressure`]); `None`: `pn` itself.
    bound_pn: Option<Vec<f64>>,
    /// The μ a layer's yield limit was divided by (a new μ loads again); `None` without one.
    yield_mu: Option<f64>,
    /// FN over the element area: the sum of a solved pressure; of an imposed one (CONTACT B = 2,
    /// 3) the prescribed FN's, as CONTACT's force ratios take FNTRUE (`m_solvpt.f90` line 586),
    /// not the sum of the pressure sampled at the element centres.
    pn_sum: f64,
    pn_max: f64,
    /// Kalker's linear d(fx/FN)/d(cx), d(fy/FN)/d(cy) at this load (shifts: Mindlin's per mm):
    /// the prescribed-force iteration's start ([`super::force`]).
    slope: [f64; 2],
    /// Mindlin's d(f/FN)/d(shift) [1/mm] at this load: the start of a shift start's iteration.
    shift_slope: [f64; 2],
}

/// The solver's state: the normal and tangential solvers (kernels and FFT plans built once per
/// grid), the normal solution of the current load, the last two steps' tractions.
struct Contact<'a> {
    p: &'a Problem,
    normal: NormalSolver,
    tangential: TangentialSolver,
    /// Steady rolling's solver where the rolling step `dq` is not the element length `dx`:
    /// CONTACT solves steady rolling with DQ = DX whatever DQ the input gives (SteadyGS;
    /// `m_sdis.f90` warns "Using DQ = DX"), so does this solver; also where the history's
    /// transient rolling takes a layer in place ([`layer_in_place`]); `None`: `tangential` serves.
    steady_dx: Option<TangentialSolver>,
    /// The solvers of the rows' own rolling distances (a table's `courant`: CONTACT's DQ changing
    /// within a history), one per distinct dq [mm] other than `[rolling]`'s.
    rolled: Vec<(f64, TangentialSolver)>,
    /// The shift from rest that starts a rolling history (`[init] kind = "shift"`); `None`: no
    /// shift start.
    shift_start: Option<TangentialSolver>,
    loaded: Option<Loaded>,
    /// The last solve (the previous traction of the next transient step).
    last: Option<StepResult>,
    /// The tractions of the step before the last (extrapolated warm start).
    older: Option<(Vec<f64>, Vec<f64>)>,
    zero: Vec<f64>,
    /// The tolerance of the outer iteration's current tangential solve where it is looser than
    /// `[contact_solver] tolerance` ([`coupled::inner_tolerance`]); `None` outside it.
    outer_tol: Option<f64>,
    /// The steady start's loading, until the first transient step ([`super::restart`]).
    after_steady: Option<SteadyStart>,
    /// A falling friction law's fixed point on the slip velocity ([`super::veldep`]).
    veldep: Option<VelDep>,
    /// The temperature law's fixed point on the surface temperature ([`super::tempdep`]).
    tempdep: Option<TempDep>,
    /// The creepages of the last solve where the sample prescribed forces ([`super::force`]).
    found: Option<[f64; 2]>,
    /// The prescribed-force iteration's last creepages and Jacobian (the next sample's start).
    outer: force::Memory,
    /// CHI = 180°: the pressure and the last solve's tractions and states back in the scene's
    /// frame (the solver's are mirrored, [`mirror`]); `None` when rolling along +x.
    shown: Option<Shown>,
    /// Whether the solver works in the mirrored frame ([`mirrored`]).
    mirrored: bool,
    /// The rolling direction [deg] `tangential` rolls along (the scene's frame; 0 when mirrored).
    chi_deg: f64,
    /// The unshifted kernel (a turn builds the shifted one anew).
    k0: Kernel,
    /// Dissimilar bodies: the normal–tangential coupling ([`coupled`]); `None`: K = 0.
    coupling: Option<Couplings>,
    /// A layer that hardens or softens: each element's yield limit ([`super::hardening`]).
    hardening: Option<Hardening>,
    /// How the last step's fixed point on the yield limits ended.
    hardened: Option<HardeningOutcome>,
    /// Both bodies' surface temperatures of the last steady solve, the scene's frame
    /// (`[material]`'s heat keys, [`heat`]).
    heated: Option<crate::physics::temperature::Temperatures>,
}

/// A field in the scene's frame where the solver works in the mirrored one.
struct Shown {
    pn: Vec<f64>,
    px: Vec<f64>,
    py: Vec<f64>,
    state: Vec<crate::solvers::stepper::ElementState>,
}

/// The history's columns of a run with falling friction.
const VELDEP_COLUMNS: [&str; 4] = ["veldep_iterations", "veldep_converged", "mu_min", "mu_max"];

/// The history's columns of a run with falling friction and surface temperatures.
const VELDEP_HEAT_COLUMNS: [&str; 6] =
    ["veldep_iterations", "veldep_converged", "mu_min", "mu_max", heat::COLUMNS[0], heat::COLUMNS[1]];

/// The history's columns of a run with the temperature law (its surface temperatures included).
const TEMPDEP_COLUMNS: [&str; 6] =
    ["tempdep_iterations", "tempdep_converged", "mu_min", "mu_max", heat::COLUMNS[0], heat::COLUMNS[1]];

/// The history's columns of a run with a layer that hardens or softens: the fixed point's
/// iterations, whether it converged, and the yield limits over the contact [MPa].
const HARDENING_COLUMNS: [&str; 4] = ["hardening_iterations", "hardening_converged", "tau_c_min_mpa", "tau_c_max_mpa"];

/// Iteration limit of the slip-velocity fixed point (CONTACT: max(1, MAXIN − 10) = 190).
const VELDEP_MAX_ITERATIONS: usize = 190;

/// The rolling distance of a row's step [mm]: its own Courant number's (a table's `courant`) or
/// `[rolling]`'s.
fn row_dq_mm(p: &Problem, s: &Sample) -> f64 {
    s.courant.map_or(p.rolling.dq_mm, |c| c * p.grid.dx_mm)
}

/// The transient solver of rolling distance `dq_mm`: a row's own ([`Contact::rolled`]) or the
/// scene's.
fn solver_for<'s>(
    tangential: &'s mut TangentialSolver,
    rolled: &'s mut [(f64, TangentialSolver)],
    dq_mm: f64,
) -> &'s mut TangentialSolver {
    match rolled.iter_mut().find(|(d, _)| *d == dq_mm) {
        Some((_, solver)) => solver,
        None => tangential,
    }
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let (g, m) = (&p.grid, &p.material);
    // An interface layer (M = 4) adds its flexibility where the material was ([`Kernel::with_layer`]).
    let kernel = |shift: f64| {
        kernel_along_x(p, shift)
            .and_then(|k| k.with_layer(m.layer_flexibility_mm_per_mpa(), [shift, 0.0]))
            .map_err(ContactRunError::Kernel)
    };
    let k0 = kernel(0.0)?;
    // A compressible sheet (B = 1) adds to the normal self-influence ([`Kernel::with_sheet`]).
    let normal = k0.clone().with_sheet(m.sheet_mm3_per_n).and_then(|k| NormalSolver::new(&k));
    let normal = normal.map_err(ContactRunError::Kernel)?;
    let (x, y) = g.centres();
    // CHI = 180°: the solver works on the grid mirrored about x = 0 ([`mirror`]).
    let mirrored = mirrored(p);
    let x = if mirrored { mirror::field_x(g.mx, &x) } else { x };
    // The first row's direction (a table's chi_deg turns the solver from row to row).
    let chi_deg = match p.loading.rows().next() {
        _ if mirrored => 0.0,
        Some(s) => s.chi_deg_or(p.rolling.chi_deg),
        None => p.rolling.chi_deg,
    };
    let mut tangential = match p.rolling.motion {
        Motion::Rolling => tangential_at(p, &k0, chi_deg, &x, &y),
        Motion::Shift => TangentialSolver::for_shifts(&k0, &x, &y),
    }
    .map_err(ContactRunError::Kernel)?;
    let solves_steady = !p.loading.is_transient() || p.loading.steady_start().is_some();
    // A steady start of a history whose rolling takes a layer in place solves with its own kernel.
    let own_steady = p.rolling.dq_mm != g.dx_mm || layer_in_place(p);
    let mut steady_dx = if solves_steady && own_steady {
        Some(TangentialSolver::new(&k0, &kernel(g.dx_mm)?, &x, &y).map_err(ContactRunError::Kernel)?)
    } else {
        None
    };
    let mut rolled: Vec<(f64, TangentialSolver)> = Vec::new();
    if p.rolling.motion == Motion::Rolling {
        for s in &p.loading.samples {
            let dq = row_dq_mm(p, s);
            if dq != p.rolling.dq_mm && !rolled.iter().any(|(d, _)| *d == dq) {
                // A transient step's kernel: a layer in place ([`layer_in_place`]).
                let ks = match layer_in_place(p) {
                    true => kernel_along_x(p, dq)
                        .and_then(|k| k.with_layer(m.layer_flexibility_mm_per_mpa(), [0.0, 0.0]))
                        .map_err(ContactRunError::Kernel)?,
                    false => kernel(dq)?,
                };
                let solver = TangentialSolver::new(&k0, &ks, &x, &y).map_err(ContactRunError::Kernel)?;
                rolled.push((dq, solver));
            }
        }
    }
    let mut shift_start = match p.loading.shift_start() {
        Some(_) => Some(TangentialSolver::for_shifts(&k0, &x, &y).map_err(ContactRunError::Kernel)?),
        None => None,
    };
    let coupling = match m.coupled() {
        true => {
            let steady_dq = if steady_dx.is_some() { g.dx_mm } else { p.rolling.dq_mm };
            let towards = direction::towards(chi_deg);
            let setup = coupled::Setup {
                mx: g.mx,
                my: g.my,
                dx_mm: g.dx_mm,
                dy_mm: g.dy_mm,
                g_mpa: m.g_mpa,
                k: m.k,
                rolling: (p.rolling.motion == Motion::Rolling).then_some((towards, p.rolling.dq_mm, steady_dq)),
                max_outer: p.contact_solver.max_outer,
            };
            Some(Couplings::new(&setup).map_err(ContactRunError::Kernel)?)
        }
        false => None,
    };
    if let Some((wx, wy)) = &p.extra_slip {
        let solvers = std::iter::once(&mut tangential).chain(steady_dx.as_mut()).chain(shift_start.as_mut());
        for solver in solvers.chain(rolled.iter_mut().map(|(_, s)| s)) {
            solver.set_extra_slip(Some((wx, wy))).map_err(ContactRunError::Kernel)?;
        }
    }
    Ok(Box::new(Contact {
        p,
        coupling,
        normal,
        tangential,
        steady_dx,
        rolled,
        shift_start,
        loaded: None,
        last: None,
        older: None,
        zero: vec![0.0; g.len()],
        outer_tol: None,
        after_steady: None,
        veldep: p.friction.is_falling().then(|| {
            let options = VelDepOptions {
                tolerance: p.contact_solver.veldep_tolerance,
                max_iterations: VELDEP_MAX_ITERATIONS,
                initial: p.contact_solver.inislp,
                omgslp: p.contact_solver.omgslp,
                // The fixed point on s can get only as tight as its solves: a tenth of its tolerance.
                solve_tolerance: p.contact_solver.tolerance.min(0.1 * p.contact_solver.veldep_tolerance),
                adaptive_solves: p.contact_solver.veldep_solves == crate::scene::VeldepSolves::Adaptive,
            };
            VelDep::new(p.friction, p.memory, options, g.mx, g.len())
        }),
        tempdep: p.friction.temperature().map(|&law| {
            let options = TempDepOptions {
                tolerance: p.contact_solver.tempdep_tolerance,
                max_iterations: p.contact_solver.tempdep_max_iterations,
                omgslp: p.contact_solver.omgslp,
                solve_tolerance: p.contact_solver.tolerance.min(0.1 * p.contact_solver.tempdep_tolerance),
                adaptive_solves: p.contact_solver.veldep_solves == crate::scene::VeldepSolves::Adaptive,
            };
            TempDep::new(law, options, g.mx, g.len())
        }),
        found: None,
        outer: force::Memory::default(),
        shown: None,
        mirrored,
        chi_deg,
        // A layer that hardens or softens: its self-flexibility C is the kernel's own element's.
        hardening: m.layer.and_then(|l| {
            let own = k0.index(0, 0);
            Hardening::new(l, g.len(), 0.5 * (k0.xx[own] + k0.yy[own]), p.contact_solver.tolerance)
        }),
        hardened: None,
        heated: None,
        k0,
    }))
}

impl Contact<'_> {
    fn params(&self, s: &Sample) -> TangentialParams {
        // Shifts: the creepages are the shifts of the step [mm], taken over a unit "dq".
        let dq_mm = match self.p.rolling.motion {
            Motion::Rolling => row_dq_mm(self.p, s),
            Motion::Shift => 1.0,
        };
        // With falling or temperature friction the bound μ_k pn_k is set per element (`set_bound`), μ = 1.
        let mu = if self.veldep.is_some() || self.tempdep.is_some() { 1.0 } else { s.mu };
        let mut t = TangentialParams::new(mu, s.cx, s.cy, s.cs, dq_mm);
        // With falling friction each solve's tolerance is the fixed point's (`veldep::inner_tolerance`).
        t.tol = self.outer_tol.unwrap_or(self.p.contact_solver.tolerance);
        t.max_iter = self.p.contact_solver.max_iterations;
        t
    }

    /// The tangential solver turned to the row's rolling direction (a table's chi_deg; CONTACT
    /// computes the influence coefficients anew for a case that reads a new CHI, C = 2).
    fn turn(&mut self, at: &Sample) -> Result<(), SolveError> {
        let chi_deg = at.chi_deg_or(self.p.rolling.chi_deg);
        if self.mirrored || chi_deg == self.chi_deg || self.p.rolling.motion != Motion::Rolling {
            return Ok(());
        }
        let (x, y) = self.p.grid.centres();
        let mut t = tangential_at(self.p, &self.k0, chi_deg, &x, &y).map_err(ContactRunError::Kernel)?;
        if let Some(l) = &self.loaded {
            // The bound's pressure, as `load` gives every solver (μ per grid row scales it).
            let bound = l.bound_pn.as_deref().unwrap_or(&l.pn);
            t.set_pressure(bound).map_err(|source| ContactRunError::Setup { fn_n: l.fn_n, source })?;
        }
        self.tangential = t;
        self.chi_deg = chi_deg;
        Ok(())
    }

    /// The sample in the solver's frame (mirrored for CHI = 180°, [`mirror::sample`]).
    fn frame(&self, at: &Sample) -> Sample {
        if self.mirrored {
            mirror::sample(at)
        } else {
            *at
        }
    }

    /// Creepages found under prescribed forces, in the scene's frame.
    fn unframe(&self, found: Option<[f64; 2]>) -> Option<[f64; 2]> {
        found.map(|c| if self.mirrored { mirror::found(c) } else { c })
    }

    fn loaded(&self) -> &Loaded {
        self.loaded.as_ref().expect("the sample loop loads before it solves")
    }

    fn record(&mut self, r: StepResult) -> Step {
        self.record_with(r, None)
    }

    /// The step's row; with falling friction the fixed point's columns ([`VELDEP_COLUMNS`]), and
    /// a fixed point that did not converge ends the row at the iteration limit.
    fn record_with(&mut self, r: StepResult, veldep: Option<VelDepOutcome>) -> Step {
        let mx = self.p.grid.mx;
        self.shown = self.mirrored.then(|| Shown {
            pn: mirror::field(mx, &self.loaded().pn),
            px: mirror::field_x(mx, &r.px),
            py: mirror::field(mx, &r.py),
            state: mirror::field(mx, &r.state),
        });
        let (px, py) = self.shown.as_ref().map_or((&r.px, &r.py), |s| (&s.px, &s.py));
        let hardened = self.hardened.take();
        let l = self.loaded();
        let mut step = Step {
            fx_over_fn: px.iter().sum::<f64>() / l.pn_sum,
            fy_over_fn: py.iter().sum::<f64>() / l.pn_sum,
            mz_nmm: moment_sum(&self.p.grid, px, py) * self.p.grid.element_area_mm2(),
            extra: vec![r.n_adhesion as f64, r.n_slip as f64, r.iterations as f64, r.residual, l.pn_max],
            termination: r.termination,
        };
        if let (Some(o), Some(h)) = (hardened, self.hardening.as_ref()) {
            let on = l.pn.iter().zip(h.tau_mpa()).filter(|(&p, _)| p > 0.0).map(|(_, &t)| t);
            let (lo, hi) = on.fold((f64::INFINITY, 0.0f64), |(lo, hi), t| (lo.min(t), hi.max(t)));
            step.extra.extend([o.iterations as f64, f64::from(u8::from(o.converged)), lo, hi]);
            step.extra[2] = o.inner_iterations as f64;
            if !o.converged {
                step.termination = crate::solvers::Termination::IterationLimit;
            }
        }
        let mu_field = self.veldep.as_ref().map(VelDep::mu).or(self.tempdep.as_ref().map(TempDep::mu));
        if let (Some(o), Some(mu)) = (veldep, mu_field) {
            let on = l.pn.iter().zip(mu).filter(|(&p, _)| p > 0.0).map(|(_, &m)| m);
            let (lo, hi) = on.fold((f64::INFINITY, 0.0f64), |(lo, hi), m| (lo.min(m), hi.max(m)));
            step.extra.extend([o.iterations as f64, f64::from(u8::from(o.converged)), lo, hi]);
            step.extra[2] = o.inner_iterations as f64;
            if !o.converged {
                step.termination = crate::solvers::Termination::IterationLimit;
            }
        }
        self.last = Some(r);
        step
    }

    /// Steady rolling with the temperature law: the fixed point on the surface temperature
    /// ([`super::tempdep`]) around the steady solve (`steady_dx` where dq ≠ dx), the
    /// temperatures in the solver's frame.
    fn tempdep_step(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let mut params = self.params(at);
        let v_mm_s = at.speed_mm_s(self.p.rolling.v_mm_s);
        let (grid, bodies) = (&self.p.grid, self.p.material.heat.as_ref().expect("the scene checks heat keys"));
        let pn = &self.loaded.as_ref().expect("the sample loop loads before it solves").pn;
        let tempdep = self.tempdep.as_mut().expect("tempdep_step runs with the temperature law");
        let solver = match self.steady_dx.as_mut() {
            Some(solver) => {
                params.dq_mm = grid.dx_mm;
                solver
            }
            None => &mut self.tangential,
        };
        let unheated = heat::unheated(grid, bodies, pn, v_mm_s);
        // The memory's rate at the slip velocity the iteration starts from (CONTACT's L = 6 keeps
        // its start, INISLP: V from above, else 0 in steady rolling).
        let start_mm_s = if self.p.contact_solver.inislp == crate::scene::InitialSlip::Above { v_mm_s } else { 0.0 };
        let theta = self.p.memory.theta(grid.dx_mm / v_mm_s, start_mm_s);
        let heated = |r: &StepResult| {
            let [one, _] = heat::temperatures(grid, bodies, pn, r, v_mm_s, false).body;
            one
        };
        let (r, outcome) = tempdep
            .step(pn, theta, unheated, heated, |g, start, tol| {
                solver.set_bound(g)?;
                solver.steady(&TangentialParams { tol, ..params }, start)
            })
            .map_err(|source| ContactRunError::Step { step: at.step, source })?;
        if r.px.iter().chain(&r.py).any(|v| !v.is_finite()) {
            return Err(SolveError::NonFinite { step: at.step });
        }
        self.older = None;
        Ok(self.record_with(r, Some(outcome)))
    }

    /// Steady rolling or a transient step with falling friction: the slip-velocity fixed point
    /// around `solve` (steady: `steady_dx` where dq ≠ dx, dt = dx/V; transient: dt = dq/V).
    fn veldep_step(&mut self, at: &Sample, steady: bool) -> Result<Step, SolveError> {
        let params = self.params(at);
        let v_mm_s = at.speed_mm_s(self.p.rolling.v_mm_s);
        let (dx, dq) = (self.p.grid.dx_mm, self.p.rolling.dq_mm);
        let motion = LawStep {
            steady,
            dt_s: if steady { dx } else { dq } / v_mm_s,
            v_mm_s,
            shift_elements: self.p.rolling.courant,
        };
        let pn = &self.loaded.as_ref().expect("the sample loop loads before it solves").pn;
        let adaptive = self.p.contact_solver.veldep_solves == crate::scene::VeldepSolves::Adaptive;
        let veldep = self.veldep.as_mut().expect("veldep_step runs with a falling law");
        let fail = |source| ContactRunError::Step { step: at.step, source };
        let (r, outcome) = if steady {
            let mut params = params;
            let solver = match self.steady_dx.as_mut() {
                Some(solver) => {
                    params.dq_mm = dx;
                    solver
                }
                None => &mut self.tangential,
            };
            veldep.step(pn, motion, |g, start, tol| {
                solver.set_bound(g)?;
                solver.steady(&TangentialParams { tol, ..params }, start)
            })
        } else {
            let (px, py) = match &self.last {
                Some(r) => (&r.px, &r.py),
                None => (&self.zero, &self.zero),
            };
            let older = self.older.as_ref().map(|(a, b)| (a.as_slice(), b.as_slice()));
            // Adaptive solves: the first solve starts with the last step's slip area on the new bound.
            let previous_state = self.last.as_ref().map(|r| r.state.as_slice()).filter(|_| adaptive);
            let tangential = &mut self.tangential;
            veldep.step(pn, motion, |g, start, tol| {
                tangential.set_bound(g)?;
                let params = TangentialParams { tol, ..params };
                match (start, previous_state) {
                    (Some(start), _) => tangential.transient_resolve_from(&params, start),
                    (None, Some(state)) => {
                        let (sx, sy) = step_start(px, py, older, state, g);
                        tangential.transient_step_from(&params, px, py, (&sx, &sy))
                    }
                    (None, None) => tangential.transient_step(&params, px, py, older),
                }
            })
        }
        .map_err(fail)?;
        if r.px.iter().chain(&r.py).any(|v| !v.is_finite()) {
            return Err(SolveError::NonFinite { step: at.step });
        }
        self.older = if steady {
            None
        } else {
            Some(match self.last.take() {
                Some(prev) => (prev.px, prev.py),
                None => (self.zero.clone(), self.zero.clone()),
            })
        };
        Ok(self.record_with(r, Some(outcome)))
    }
}

impl Contact<'_> {
    /// A steady row with surface temperatures (`[material]`'s heat keys): both bodies' fields
    /// from the last solve (CONTACT's `calc_temp` after the tangential problem; with the
    /// temperature law body 1's is its fixed point's last iterate, [`TempDep::temperature_c`]),
    /// their largest over the contact as the row's [`heat::COLUMNS`].
    fn with_temperatures(&mut self, at: &Sample, mut step: Step) -> Step {
        let (Some(bodies), Some(r)) = (self.p.material.heat.as_ref(), self.last.as_ref()) else { return step };
        let pn = &self.loaded().pn;
        let v_mm_s = at.speed_mm_s(self.p.rolling.v_mm_s);
        let mut t = heat::temperatures(&self.p.grid, bodies, pn, r, v_mm_s, self.mirrored);
        // The temperature law: body 1's is its fixed point's last iterate (CONTACT's `temp1`).
        if let Some(iterate) = self.tempdep.as_ref().map(TempDep::temperature_c) {
            let mx = self.p.grid.mx;
            t.body[0] = if self.mirrored { mirror::field(mx, iterate) } else { iterate.to_vec() };
        }
        let shown_pn = self.shown.as_ref().map_or(pn, |s| &s.pn);
        step.extra.extend(heat::maxima(&t, shown_pn));
        self.heated = Some(t);
        step
    }

    /// The sample's undeformed distance: its own (CONTACT's IBASE = 1 per case, in CONTACT's
    /// coordinates x_C = −x), else the geometry's at its load.
    fn undeformed_mm(&self, at: &Sample) -> Vec<f64> {
        let p = self.p;
        match at.h_coefficients {
            Some(b) => {
                let (x, y) = p.grid.centres();
                x.iter()
                    .zip(&y)
                    .map(|(x, y)| {
                        let xc = -x;
                        b[0] * xc * xc + b[1] * xc * y + b[2] * y * y + b[3] * xc + b[4] * y + b[5]
                    })
                    .collect()
            }
            None => p.geometry.undeformed_distance_mm(&p.grid, at.fn_n, &p.material),
        }
    }

    /// The pressure at the sample's FN: Hertz's imposed (`[normal] pressure`, CONTACT B = 2, 3:
    /// at the element centres, `m_sdis.f90` lines 645-690), the geometry's own where it has solved
    /// it (with the uniform elements' influence functions), else the normal problem.
    fn normal_by_force(&mut self, at: &Sample, pressure: NormalPressure) -> Result<Vec<f64>, ContactRunError> {
        let (p, fn_n) = (self.p, at.fn_n);
        if let Some(shape) = pressure.shape() {
            let e = p.geometry.ellipse_at(fn_n);
            return Ok(shape.on_grid(&p.grid, fn_n, e.a_mm, e.b_mm));
        }
        // The geometry solves with elastic coefficients: viscoelastic bodies solve their own.
        let geometry_solves =
            at.h_coefficients.is_none() && p.contact_solver.influence == Basis::Constant && p.material.visco.is_none();
        if let Some(pn) = geometry_solves.then(|| p.geometry.normal_pressure_mpa(fn_n)).flatten() {
            return Ok(pn);
        }
        let h = self.undeformed_mm(at);
        let normal = self
            .normal
            .solve(&h, fn_n, &NormalParams::default())
            .map_err(|source| ContactRunError::Normal { fn_n, source })?;
        if !normal.converged {
            let (iterations, residual) = (normal.iterations, normal.residual);
            return Err(ContactRunError::NormalNotConverged { fn_n, iterations, residual });
        }
        Ok(normal.pn_mpa)
    }

    /// The pressure at the approach `pen_mm` (CONTACT N = 0) on the sample's undeformed distance.
    fn normal_by_approach(&mut self, at: &Sample, pen_mm: f64) -> Result<Vec<f64>, ContactRunError> {
        let h = self.undeformed_mm(at);
        let normal = self
            .normal
            .solve_approach(&h, pen_mm, &NormalParams::default())
            .map_err(|source| ContactRunError::Approach { pen_mm, source })?;
        if !normal.converged {
            let (iterations, residual) = (normal.iterations, normal.residual);
            return Err(ContactRunError::ApproachNotConverged { pen_mm, iterations, residual });
        }
        Ok(normal.pn_mpa)
    }
}

/// A solve's tractions and the creepages found under prescribed forces.
type Solved = (StepResult, Option<[f64; 2]>);

/// A layer that hardens or softens, the friction bound's pressure [MPa] and where the step's
/// limits and outcome are put ([`Hardening::step`]).
type Limits<'h, 'k> = (&'h Hardening, &'h [f64], &'k mut Option<(Vec<f64>, HardeningOutcome)>);

/// A transient step (rolling or a shift) after the tractions `(px, py)`; with `limits` the fixed
/// point on the layer's yield limits around each solve ([`Hardening::step`], CONTACT's `plstrc`
/// within its ConvexGS sweeps), the final solve's limits put in `limits`' slot.
fn transient_with_limits(
    solver: &mut TangentialSolver,
    q: &TangentialParams,
    (px, py): (&[f64], &[f64]),
    older: Option<(&[f64], &[f64])>,
    start: Option<(&[f64], &[f64])>,
    limits: Option<Limits<'_, '_>>,
) -> Result<StepResult, ContactError> {
    let Some((h, friction_pn, kept)) = limits else {
        return match start {
            Some(start) => solver.transient_step_from(q, px, py, start),
            None => solver.transient_step(q, px, py, older),
        };
    };
    let (r, tau, outcome) = h.step(friction_pn, q.mu, q.tol, |bound, start, tol| {
        solver.set_bound(bound)?;
        let q = &TangentialParams { tol, ..*q };
        match start {
            Some(start) => solver.transient_resolve_from(q, start),
            None => solver.transient_step(q, px, py, older),
        }
    })?;
    *kept = Some((tau, outcome));
    Ok(r)
}

impl Contact<'_> {
    /// A steady solve (prescribed forces: their creepages sought), warm started from `start`
    /// (the last outer iteration's tractions), else from the solver's previous steady solution.
    fn steady_solve(&mut self, at: &Sample, start: Option<&StepResult>) -> Result<Solved, SolveError> {
        let mut params = self.params(at);
        let solver = match self.steady_dx.as_mut() {
            Some(solver) => {
                params.dq_mm = self.p.grid.dx_mm;
                solver
            }
            None => {
                // The steady solve rolls dx = [rolling]'s dq whatever a row's own courant says.
                params.dq_mm = self.p.rolling.dq_mm;
                &mut self.tangential
            }
        };
        let l = self.loaded.as_ref().expect("loaded before a solve");
        let (slope, pn_sum) = (l.slope, l.pn_sum);
        let start = start.map(|r| (r.px.as_slice(), r.py.as_slice()));
        let Some(h) = self.hardening.as_ref() else {
            return force::solve_sample(at, &params, slope, pn_sum, &mut self.outer, |q| solver.steady(q, start))
                .map_err(|source| ContactRunError::Step { step: at.step, source }.into());
        };
        // A layer that hardens or softens: the limits carried from the element upstream.
        let friction_pn = l.bound_pn.as_deref().unwrap_or(&l.pn);
        let grid = (self.p.grid.mx, solver.steady_self_flexibility_mm_per_mpa());
        let mut kept: Option<(Vec<f64>, HardeningOutcome)> = None;
        let solved = force::solve_sample(at, &params, slope, pn_sum, &mut self.outer, |q| {
            let (r, tau, outcome) = h.steady(friction_pn, q.mu, grid, |bound, warm| {
                solver.set_bound(bound)?;
                solver.steady(q, warm.or(start))
            })?;
            kept = Some((tau, outcome));
            Ok(r)
        })
        .map_err(|source| ContactRunError::Step { step: at.step, source })?;
        self.keep_hardened(kept);
        Ok(solved)
    }

    /// The yield limits of a solve's final iterate kept for the next step, with how its fixed
    /// point ended ([`Hardening`]); nothing without a layer that hardens or softens.
    fn keep_hardened(&mut self, kept: Option<(Vec<f64>, HardeningOutcome)>) {
        if let (Some(h), Some((tau, outcome))) = (self.hardening.as_mut(), kept) {
            h.keep(tau);
            self.hardened = Some(outcome);
        }
    }

    /// The shift from rest of a shift start.
    fn shift_solve(&mut self, at: &Sample) -> Result<Solved, SolveError> {
        let params = TangentialParams { dq_mm: 1.0, ..self.params(at) };
        let (slope, pn_sum) = self.loaded.as_ref().map(|l| (l.shift_slope, l.pn_sum)).expect("loaded before a solve");
        let solver = self.shift_start.as_mut().expect("built for a shift start");
        let zero = &self.zero;
        // A layer that hardens or softens: the fixed point on its limits, as in a shift history.
        let l = self.loaded.as_ref().expect("loaded before a solve");
        let friction_pn = l.bound_pn.as_deref().unwrap_or(&l.pn);
        let hardening = self.hardening.as_ref();
        let mut kept: Option<(Vec<f64>, HardeningOutcome)> = None;
        let solved = force::solve_sample(at, &params, slope, pn_sum, &mut force::Memory::default(), |q| {
            let limits = hardening.map(|h| (h, friction_pn, &mut kept));
            transient_with_limits(solver, q, (zero, zero), None, None, limits)
        })
        .map_err(|source| ContactRunError::Step { step: at.step, source })?;
        self.keep_hardened(kept);
        Ok(solved)
    }

    /// A transient step (rolling or a shift) after the last step's tractions; with a layer that
    /// hardens or softens, the fixed point on its yield limits around each solve, the limits of
    /// the step's final solve kept ([`Hardening`]).
    fn transient_solve(
        &mut self,
        at: &Sample,
        params: &TangentialParams,
        start: Option<&StepResult>,
    ) -> Result<Solved, SolveError> {
        let (px, py) = match &self.last {
            Some(r) => (&r.px, &r.py),
            None => (&self.zero, &self.zero),
        };
        let older = self.older.as_ref().map(|(a, b)| (a.as_slice(), b.as_slice()));
        let l = self.loaded.as_ref().expect("loaded before a solve");
        let (slope, pn_sum) = (l.slope, l.pn_sum);
        let friction_pn = l.bound_pn.as_deref().unwrap_or(&l.pn);
        let tangential = solver_for(&mut self.tangential, &mut self.rolled, params.dq_mm);
        let hardening = self.hardening.as_ref();
        let mut kept: Option<(Vec<f64>, HardeningOutcome)> = None;
        let start = start.map(|r| (r.px.as_slice(), r.py.as_slice()));
        let params = &TangentialParams { tol: self.outer_tol.unwrap_or(params.tol), ..*params };
        let solved = force::solve_sample(at, params, slope, pn_sum, &mut self.outer, |q| {
            let limits = hardening.map(|h| (h, friction_pn, &mut kept));
            transient_with_limits(tangential, q, (px, py), older, start, limits)
        })
        .map_err(|source| ContactRunError::Step { step: at.step, source })?;
        self.keep_hardened(kept);
        Ok(solved)
    }

    /// `solve` as it is for K = 0; for dissimilar bodies the outer iteration ([`coupled`]):
    /// the tangential solve with the pressure's slip, then the normal problem with the traction's
    /// normal displacement (the traction extrapolated, [`coupled::Extrapolation`]) and the
    /// tangential solve again (warm started from the last), until the
    /// change of (pn, px, py) is within the tolerance after a solve at the tolerance or
    /// `max_outer` solves were made (then the step ends at the iteration limit); the earlier
    /// solves at [`coupled::inner_tolerance`].
    fn solve_coupled(
        &mut self,
        at: &Sample,
        kind: Kind,
        mut solve: impl FnMut(&mut Self, Option<&StepResult>) -> Result<Solved, SolveError>,
    ) -> Result<Solved, SolveError> {
        let Some(max_outer) = self.coupling.as_ref().map(|c| c.max_outer) else {
            return solve(self, None);
        };
        // The first normal problem takes the last solve's traction (CONTACT's initial estimate,
        // I = 1): a history's next step starts near its fixed point.
        if let Some(last) = self.last.take().filter(|_| max_outer > 1) {
            let done = self.normal_with_traction(at, (&last.px, &last.py));
            self.last = Some(last);
            done?;
        }
        self.coupled_slip(kind).map_err(|source| ContactRunError::Step { step: at.step, source })?;
        let tol = self.p.contact_solver.tolerance;
        self.outer_tol = (max_outer > 1).then(|| coupled::inner_tolerance(tol, None));
        let out = solve(self, None);
        self.outer_tol = None;
        let mut out = out?;
        let mut converged = true;
        let mut traction = coupled::Extrapolation::default();
        let mut relative = f64::INFINITY;
        for i in 1..max_outer {
            let before = [self.loaded().pn.clone(), out.0.px.clone(), out.0.py.clone()];
            let (px, py) = traction.next(&out.0.px, &out.0.py);
            self.normal_with_traction(at, (&px, &py))?;
            self.coupled_slip(kind).map_err(|source| ContactRunError::Step { step: at.step, source })?;
            // The last allowed solve is made at the tolerance.
            let inner = if i + 1 == max_outer { tol } else { coupled::inner_tolerance(tol, Some(relative)) };
            self.outer_tol = Some(inner);
            let next = solve(self, Some(&out.0));
            self.outer_tol = None;
            out = next?;
            let (change, size) =
                coupled::change([&before[0], &before[1], &before[2]], [&self.loaded().pn, &out.0.px, &out.0.py]);
            relative = relative.min(change / size);
            converged = inner <= tol && change <= coupled::OUTER_FACTOR * tol * size;
            if converged {
                break;
            }
        }
        if !converged && out.0.termination == crate::solvers::Termination::Converged {
            out.0.termination = crate::solvers::Termination::IterationLimit;
        }
        let pn = self.loaded().pn.clone();
        if let Some(c) = self.coupling.as_mut() {
            c.previous_pn = pn;
        }
        Ok(out)
    }

    /// The pressure's slip for a solve of `kind`, given to the solver that makes it.
    fn coupled_slip(&mut self, kind: Kind) -> Result<(), ContactError> {
        let (Some(c), Some(l)) = (self.coupling.as_mut(), self.loaded.as_ref()) else { return Ok(()) };
        let (sx, sy) = c.slip(kind, &l.pn)?;
        let solver = match kind {
            Kind::Steady => self.steady_dx.as_mut().unwrap_or(&mut self.tangential),
            Kind::Rolling => &mut self.tangential,
            Kind::Shift => self
                .shift_start
                .as_mut()
                .filter(|_| self.p.rolling.motion == Motion::Rolling)
                .unwrap_or(&mut self.tangential),
        };
        solver.set_coupled_slip(Some((sx, sy)))
    }

    /// The normal problem again on the undeformed distance plus the normal displacement of the
    /// traction `(px, py)` (the solver's frame), at the sample's FN or approach; every solver takes the
    /// new pressure.
    fn normal_with_traction(&mut self, at: &Sample, (px, py): (&[f64], &[f64])) -> Result<(), SolveError> {
        let (p, mx) = (self.p, self.p.grid.mx);
        let c = self.coupling.as_mut().expect("coupled");
        let un = c.normal_of(px, py).map_err(|source| ContactRunError::Step { step: at.step, source })?;
        let un = if self.mirrored { mirror::field(mx, &un) } else { un };
        let h: Vec<f64> = self.undeformed_mm(at).iter().zip(&un).map(|(h, u)| h + u).collect();
        // The outer iteration's last pressure starts the next normal solve (a nearby problem).
        let last = self.loaded.as_ref().map(|l| if self.mirrored { mirror::field(mx, &l.pn) } else { l.pn.clone() });
        let solved = match at.pen_mm {
            Some(pen_mm) => self
                .normal
                .solve_approach_from(&h, pen_mm, &NormalParams::default(), last.as_deref())
                .map_err(|source| ContactRunError::Approach { pen_mm, source })?,
            None => self
                .normal
                .solve_from(&h, at.fn_n, &NormalParams::default(), last.as_deref())
                .map_err(|source| ContactRunError::Normal { fn_n: at.fn_n, source })?,
        };
        if !solved.converged {
            let (iterations, residual) = (solved.iterations, solved.residual);
            return Err(ContactRunError::NormalNotConverged { fn_n: at.fn_n, iterations, residual }.into());
        }
        let pn = if self.mirrored { mirror::field(mx, &solved.pn_mpa) } else { solved.pn_mpa };
        let pn_sum: f64 = pn.iter().sum();
        if pn_sum <= 0.0 {
            return Err(ContactRunError::NoContact { mx, my: p.grid.my, fn_n: at.fn_n }.into());
        }
        let solvers =
            std::iter::once(&mut self.tangential).chain(self.steady_dx.as_mut()).chain(self.shift_start.as_mut());
        for solver in solvers {
            solver.set_pressure(&pn).map_err(|source| ContactRunError::Setup { fn_n: at.fn_n, source })?;
        }
        let l = self.loaded.as_mut().expect("loaded before a solve");
        l.pn_max = pn.iter().fold(0.0f64, |a, &b| a.max(b));
        l.fn_n = pn_sum * p.grid.element_area_mm2();
        l.pn_sum = pn_sum;
        l.pn = pn;
        Ok(())
    }
}

impl Stepper for Contact<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        let p = self.p;
        let pressure = p.normal.of_row(at.step == 0 && p.loading.start().is_some());
        let key = (at.fn_n, at.pen_mm, at.h_coefficients, pressure);
        let yield_mu = p.material.layer.and_then(|l| l.yield_mpa).map(|_| at.mu);
        if self.loaded.as_ref().is_some_and(|l| l.key == key && l.yield_mu == yield_mu) {
            return Ok(());
        }
        let (pn_mpa, fn_n) = match at.pen_mm {
            Some(pen_mm) => {
                let pn = self.normal_by_approach(at, pen_mm)?;
                let fn_n = pn.iter().sum::<f64>() * p.grid.element_area_mm2();
                (pn, fn_n)
            }
            None => (self.normal_by_force(at, pressure)?, at.fn_n),
        };
        let pn_mpa = if self.mirrored { mirror::field(p.grid.mx, &pn_mpa) } else { pn_mpa };
        let pn_sum: f64 = match pressure {
            NormalPressure::Solved => pn_mpa.iter().sum(),
            _ if pn_mpa.iter().any(|&v| v > 0.0) => fn_n / p.grid.element_area_mm2(),
            _ => 0.0,
        };
        if pn_sum <= 0.0 {
            return Err(ContactRunError::NoContact { mx: p.grid.mx, my: p.grid.my, fn_n }.into());
        }
        // μ per grid row: every solve takes μ_max on the pressure scaled per row (rows keep their
        // place under the mirror of CHI = 180°, which flips x only).
        let bound_pn = p.friction_rows.as_ref().map(|rows| rows.bound_pressure(p.grid.mx, &pn_mpa));
        // A layer's yield limit: the bound min(μ pn, τ_c0) (CONTACT's TAU_C0 with K_TAU = 0); one
        // that hardens or softens sets it per step ([`super::hardening`]).
        let fixed = p.material.layer.filter(|l| !l.hardens());
        let capped = fixed.and_then(|l| l.capped_pressure(at.mu, bound_pn.as_deref().unwrap_or(&pn_mpa)));
        let bound_pn = capped.or(bound_pn);
        let solvers =
            std::iter::once(&mut self.tangential).chain(self.steady_dx.as_mut()).chain(self.shift_start.as_mut());
        let solvers = solvers.chain(self.rolled.iter_mut().map(|(_, solver)| solver));
        for solver in solvers {
            let bound = bound_pn.as_deref().unwrap_or(&pn_mpa);
            solver.set_pressure(bound).map_err(|source| ContactRunError::Setup { fn_n, source })?;
        }
        let pn_max = pn_mpa.iter().fold(0.0f64, |a, &b| a.max(b));
        // A row's own undeformed distance: the equivalent ellipse of its pressure (as the geometry's).
        let e = match at.h_coefficients {
            Some(_) => equivalent_ellipse(&p.grid, &pn_mpa, fn_n).unwrap_or_else(|| p.geometry.ellipse_at(fn_n)),
            None => p.geometry.ellipse_at(fn_n),
        };
        let shift_slope = [mindlin_stiffness_n_mm(p, e.a_mm * e.b_mm) / fn_n; 2];
        let slope = match p.rolling.motion {
            Motion::Rolling => {
                let linear = LinearTheory::new(p.material.g_mpa, e.a_mm, e.b_mm, fn_n);
                [linear.forces(&p.coefficients, (1.0, 0.0, 0.0)).0, linear.forces(&p.coefficients, (0.0, 1.0, 0.0)).1]
            }
            Motion::Shift => shift_slope,
        };
        if self.loaded.is_some() && p.rolling.motion == Motion::Shift {
            self.outer.from_rest();
        }
        self.loaded = Some(Loaded { key, fn_n, pn: pn_mpa, bound_pn, yield_mu, pn_sum, pn_max, slope, shift_slope });
        self.older = None;
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.turn(at)?;
        let at = &self.frame(at);
        if self.veldep.is_some() {
            let step = self.veldep_step(at, true)?;
            return Ok(self.with_temperatures(at, step));
        }
        if self.tempdep.is_some() {
            let step = self.tempdep_step(at)?;
            return Ok(self.with_temperatures(at, step));
        }
        let (r, found) = self.solve_coupled(at, Kind::Steady, |c, start| c.steady_solve(at, start))?;
        self.found = self.unframe(found);
        self.older = None;
        self.after_steady = Some(SteadyStart::of(at));
        let step = self.record(r);
        Ok(self.with_temperatures(at, step))
    }

    /// The shift from rest (CONTACT T = 1, P = 2): its traction is the previous traction of the
    /// first rolling step; the prescribed-force iteration then starts afresh.
    fn shift(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let (r, found) = self.solve_coupled(at, Kind::Shift, |c, _| c.shift_solve(at))?;
        self.found = found;
        if r.px.iter().chain(&r.py).any(|v| !v.is_finite()) {
            return Err(SolveError::NonFinite { step: at.step });
        }
        self.older = None;
        Ok(self.record(r))
    }

    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.turn(at)?;
        let at = &self.frame(at);
        if self.veldep.is_some() {
            return self.veldep_step(at, false);
        }
        let params = self.params(at);
        self.found = None;
        // Rolling with a layer that hardens or softens: the limits move with the material first.
        if let (Some(h), Motion::Rolling) = (self.hardening.as_mut(), self.p.rolling.motion) {
            h.carry(self.p.grid.mx, params.dq_mm / self.p.grid.dx_mm);
        }
        // Prescribed forces: the plain transient step, its creepages sought by the outer iteration.
        let start = self.after_steady.take().filter(|s| s.load_changed(at) && !at.prescribes_force());
        // Dissimilar bodies (the outer iteration solves every step to its tolerance) and a layer
        // that hardens or softens (the fixed point on its limits) take the step in full.
        let start = start.filter(|_| self.coupling.is_none() && self.hardening.is_none());
        if let (Some(start), Some(steady), SteadyRestart::Contact) =
            (start, &self.last, self.p.contact_solver.steady_restart)
        {
            let l = self.loaded.as_ref().expect("the sample loop loads before it solves");
            let pn = l.bound_pn.as_ref().unwrap_or(&l.pn);
            let tangential = solver_for(&mut self.tangential, &mut self.rolled, params.dq_mm);
            let slip_at =
                |px: &[f64], py: &[f64]| tangential.transient_slip(&params, (&steady.px, &steady.py), (px, py));
            let restart = contact_restart(&start, steady, at, pn, slip_at)
                .map_err(|source| ContactRunError::Step { step: at.step, source })?;
            if let Some(r) = restart {
                self.older = self.last.take().map(|prev| (prev.px, prev.py));
                return Ok(self.record(r));
            }
        }
        let kind = if self.p.rolling.motion == Motion::Shift { Kind::Shift } else { Kind::Rolling };
        let (r, found) = self.solve_coupled(at, kind, |c, start| c.transient_solve(at, &params, start))?;
        self.found = self.unframe(found);
        if r.px.iter().chain(&r.py).any(|v| !v.is_finite()) {
            return Err(SolveError::NonFinite { step: at.step });
        }
        self.older = Some(match self.last.take() {
            Some(prev) => (prev.px, prev.py),
            None => (self.zero.clone(), self.zero.clone()),
        });
        Ok(self.record(r))
    }

    fn more_columns(&self) -> &'static [&'static str] {
        let heat = self.p.material.heat.is_some();
        match (self.hardening.is_some(), self.veldep.is_some(), heat) {
            _ if self.tempdep.is_some() => &TEMPDEP_COLUMNS,
            (true, _, _) => &HARDENING_COLUMNS,
            (_, true, true) => &VELDEP_HEAT_COLUMNS,
            (_, true, false) => &VELDEP_COLUMNS,
            (_, false, true) => &heat::COLUMNS,
            _ => &[],
        }
    }

    fn solved_creepage(&self) -> Option<[f64; 2]> {
        self.found
    }

    fn solved_fn_n(&self) -> Option<f64> {
        self.loaded.as_ref().filter(|l| l.key.1.is_some()).map(|l| l.fn_n)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        let (l, r) = (self.loaded.as_ref()?, self.last.as_ref()?);
        let temperature_c = self.heated.as_ref().map(|t| [t.body[0].as_slice(), t.body[1].as_slice()]);
        let (pn, px, py, state) = match &self.shown {
            Some(s) => (&s.pn, &s.px, &s.py, &s.state),
            None => (&l.pn, &r.px, &r.py, &r.state),
        };
        Some(FieldView {
            grid: &self.p.grid,
            pressure_mpa: pn,
            tx_mpa: px,
            ty_mpa: py,
            state: Some(state),
            temperature_c,
        })
    }
}
