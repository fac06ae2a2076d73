//! Surface temperatures of frictional heating in steady rolling (CONTACT's H digit; user guide,
//! "Calculation of contact temperatures"; Ertz & Knothe 2002): each grid row a strip of the moving
//! half-spaces, heated by the frictional power density q = |τ| |ṡ| of its slipping elements, at a
//! Péclet number so high that heat flows only into the depth (the 1-D solution of a moving
//! surface source, Carslaw & Jaeger §2.9: ΔT(x) = ∫ q(ξ) dξ / (β √(π V (x − ξ))) per body).
//!
//! Both bodies' surfaces touch in the contact, so the heat splits by effusivity β = √(λρc)
//! (Ertz's partition ε = β1/(β1 + β2)) and both rise by the same 2 Σ q_m w_m / ((β1 + β2) √(πV)).
//! Material entering the contact jumps to the mean T̄ = (β1 T1 + β2 T2)/(β1 + β2); behind the
//! trailing edge each body relaxes to its bulk value as after a step of contact time
//! (T_a = T_a0 + (T̄ − T_a0) (2/π) asin √(L/X), L the row's contact length, X the distance from
//! its leading edge), the frictional rise continuing beyond the edge. Units: mm, N, s, °C.
//!
//! Discretised per element of constant q as CONTACT does (`m_temperature.f90`): upstream elements
//! by the exact integral over their length, the element's own source with the weight 2√(dx/2),
//! twice the exact integral up to its centre. So under a uniform source the temperature stands
//! q √(dx/2) / ((β1 + β2) √(πV)) above the continuous solution at every element (the upstream sum
//! telescopes), a bias that vanishes as √dx; kept to reproduce CONTACT's printed temperatures.

use super::Grid;

/// One body's thermal constants (CONTACT's BKTEMP, HEATCP, LAMBDA, DENS).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Thermal {
    /// The bulk (initial) temperature T0 [°C].
    pub bulk_c: f64,
    /// The specific heat capacity c_p [J/(kg °C)].
    pub heat_capacity_j_per_kg_c: f64,
    /// The thermal conductivity λ [W/(mm °C)].
    pub conductivity_w_per_mm_c: f64,
    /// The density ρ [kg/mm³].
    pub density_kg_per_mm3: f64,
}

impl Thermal {
    /// The effusivity β = √(λ ρ c_p) in N/(mm √s °C) (1 W = 10³ N mm/s, 1 J = 10³ N mm).
    pub fn effusivity(&self) -> f64 {
        1e3 * (self.conductivity_w_per_mm_c * self.density_kg_per_mm3 * self.heat_capacity_j_per_kg_c).sqrt()
    }
}

/// The heat sources of one steady solve on the grid, in the frame where material moves towards
/// increasing i (the leading edge of each row at its lowest contact element).
#[derive(Debug, Clone, Copy)]
pub struct Heating<'a> {
    pub grid: &'a Grid,
    /// Whether each element is in contact (pn > 0).
    pub contact: &'a [bool],
    /// The frictional power density q = |τ| |ṡ| of each element [N/(mm s)] (0 where it adheres).
    pub power_density: &'a [f64],
    /// The rolling speed V [mm/s].
    pub v_mm_s: f64,
}

/// Both bodies' surface temperatures per element [°C].
#[derive(Debug, Clone, PartialEq)]
pub struct Temperatures {
    pub body: [Vec<f64>; 2],
}

impl Temperatures {
    /// The largest surface temperature of body `a` (0 or 1) over the contact elements [°C]
    /// (CONTACT prints MAX(T1), MAX(T2) over its interior elements); −∞ without contact.
    pub fn max_in_contact(&self, a: usize, contact: &[bool]) -> f64 {
        self.body[a].iter().zip(contact).filter(|(_, &c)| c).map(|(&t, _)| t).fold(f64::NEG_INFINITY, f64::max)
    }
}

/// The surface temperatures of both bodies under `h` ([module docs](self)).
pub fn surface_temperatures(h: &Heating, bodies: &[Thermal; 2]) -> Temperatures {
    let (mx, my, dx) = (h.grid.mx, h.grid.my, h.grid.dx_mm);
    let beta = [bodies[0].effusivity(), bodies[1].effusivity()];
    let mean_c = (beta[0] * bodies[0].bulk_c + beta[1] * bodies[1].bulk_c) / (beta[0] + beta[1]);
    let rise_per_sum = 2.0 / ((beta[0] + beta[1]) * (std::f64::consts::PI * h.v_mm_s).sqrt());
    let mut body = [vec![bodies[0].bulk_c; mx * my], vec![bodies[1].bulk_c; mx * my]];
    let half = 0.5 * dx;
    for j in 0..my {
        let row = j * mx..(j + 1) * mx;
        let contact = &h.contact[row.clone()];
        let q = &h.power_density[row.clone()];
        if let (Some(first), Some(last)) = (contact.iter().position(|&c| c), contact.iter().rposition(|&c| c)) {
            let length_mm = (last - first + 1) as f64 * dx;
            for (i, &inside) in contact.iter().enumerate().skip(first) {
                let k = j * mx + i;
                for (a, t) in body.iter_mut().enumerate() {
                    t[k] = if inside {
                        mean_c
                    } else if i > last {
                        let beyond_mm = length_mm + (i - last) as f64 * dx - half;
                        let relaxed = std::f64::consts::FRAC_2_PI * (length_mm / beyond_mm).sqrt().asin();
                        bodies[a].bulk_c + (mean_c - bodies[a].bulk_c) * relaxed
                    } else {
                        bodies[a].bulk_c
                    };
                }
            }
        }
        // The frictional rise: each upstream element's source over its length (∫ dξ/√(x − ξ) over
        // the element, halved with the 1/2 of `rise_per_sum`), the element's own weighted 2√(dx/2)
        // as CONTACT's `calc_temp_steady` (twice the integral up to its centre, [module docs](self)).
        for i in 0..mx {
            let mut sum = 2.0 * q[i] * half.sqrt();
            for (m, &qm) in q.iter().enumerate().take(i) {
                if qm != 0.0 {
                    let d = (i - m) as f64 * dx;
                    sum += qm * ((d + half).sqrt() - (d - half).sqrt());
                }
            }
            for t in body.iter_mut() {
                t[j * mx + i] += rise_per_sum * sum;
            }
        }
    }
    Temperatures { body }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel(bulk_c: f64) -> Thermal {
        Thermal { bulk_c, heat_capacity_j_per_kg_c: 450.0, conductivity_w_per_mm_c: 50e-3, density_kg_per_mm3: 7.85e-6 }
    }

    #[test]
    fn a_uniform_source_rises_as_the_root_of_the_time_heated() {
        // One row, all in contact, q uniform: the continuous solution ΔT(x) = 2 q √x / ((β1 + β2)
        // √(πV)) at each centre x = (i + 1/2) dx from the leading edge (Carslaw & Jaeger §2.9),
        // plus CONTACT's self-weight bias 2 q √(dx/2) / ((β1 + β2) √(πV)) (the upstream sum telescopes).
        let grid = Grid::new(40, 1, 5.0, 0.5);
        let contact = vec![true; 40];
        let q = vec![3.0e4; 40];
        let h = Heating { grid: &grid, contact: &contact, power_density: &q, v_mm_s: 3.0e4 };
        let b = [steel(20.0), steel(20.0)];
        let t = surface_temperatures(&h, &b);
        let beta = b[0].effusivity();
        for i in 0..40 {
            let x = (i as f64 + 0.5) * 0.25;
            let per_root = 2.0 * 3.0e4 / (2.0 * beta * (std::f64::consts::PI * 3.0e4).sqrt());
            let want = 20.0 + per_root * (x.sqrt() + 0.125f64.sqrt());
            assert!((t.body[0][i] - want).abs() < 1e-9 * want, "{i}: {} {want}", t.body[0][i]);
            assert_eq!(t.body[0][i], t.body[1][i]);
        }
    }

    #[test]
    fn without_heat_the_bodies_meet_at_the_effusivity_mean_and_relax_behind() {
        let grid = Grid::new(10, 1, 5.0, 0.5);
        let contact: Vec<bool> = (0..10).map(|i| (2..6).contains(&i)).collect();
        let q = vec![0.0; 10];
        let h = Heating { grid: &grid, contact: &contact, power_density: &q, v_mm_s: 1e4 };
        let t = surface_temperatures(&h, &[steel(0.0), steel(150.0)]);
        assert_eq!(t.body[0][1], 0.0);
        assert_eq!(t.body[1][1], 150.0);
        assert_eq!(t.body[0][3], 75.0);
        assert_eq!(t.max_in_contact(1, &contact), 75.0);
        // 0.5 mm behind the trailing edge: X = 4.5 mm after L = 4 mm of contact.
        let relaxed = std::f64::consts::FRAC_2_PI * (4.0f64 / 4.5).sqrt().asin();
        assert!((t.body[0][6] - 75.0 * relaxed).abs() < 1e-12);
        assert!((t.body[1][6] - (150.0 - 75.0 * relaxed)).abs() < 1e-12);
    }
}
