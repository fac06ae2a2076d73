//! Elastic constants of two quasi-identical bodies (thesis Eq. 2.1 with K = 0).

/// Combined elastic constants of the two bodies.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Material {
    /// Combined shear modulus G [MPa] (thesis Table 4.1 prints "82000 GPa"; it is 82000 MPa).
    pub g_mpa: f64,
    /// Combined Poisson's ratio ν [-].
    pub poisson: f64,
    /// Young's modulus E [MPa]; `2 G (1 + ν)` unless given explicitly.
    pub e_mpa: f64,
    /// Kalker's difference parameter K [-] of two dissimilar bodies ([`combine_bodies`]); 0 for
    /// quasi-identical bodies (no normal–tangential coupling).
    #[serde(skip_serializing_if = "is_zero")]
    pub k: f64,
    /// The two bodies' own shear moduli [MPa] and Poisson's ratios where the scene gives them
    /// (`[material] g1_mpa` … `poisson2`); `None`: the combined constants only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bodies: Option<Bodies>,
    /// An interface layer between the bodies (`[material] layer_g_mpa`, `layer_thickness_mm`;
    /// CONTACT's M = 4); `None`: the bodies touch.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub layer: Option<Layer>,
    /// Both bodies a viscoelastic standard linear solid (`[material] visco_ratio`,
    /// `visco_time_s`; CONTACT's M = 1 with FG 1 = FG 2, TC 1 = TC 2); `None`: elastic.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub visco: Option<Visco>,
    /// Both bodies' thermal constants where the scene asks for surface temperatures
    /// (`[material] bulk1_c` …; CONTACT's H = 3, [`super::temperature`]); `None`: none computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heat: Option<[super::temperature::Thermal; 2]>,
    /// A thin compressible sheet's flexibility L_z [mm³/N] (`[material]
    /// sheet_flexibility_mm3_per_n`; CONTACT's B = 1, FLXZ), added to the normal self-influence
    /// ([`super::halfspace::sheet`]); 0: none.
    #[serde(skip_serializing_if = "is_zero")]
    pub sheet_mm3_per_n: f64,
    /// Blanco-Lorenzo's conformal correction of the influence coefficients on a curved reference
    /// (`[material] blanco_inclination`, `blanco_variant`; CONTACT's C3 = 4,
    /// [`super::halfspace::blanco`]); `None`: the half-space's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub blanco: Option<super::halfspace::blanco::Blanco>,
}

/// A standard linear solid in its Kelvin–Voigt form (CONTACT's M = 1, user guide "Viscoelastic
/// materials"): creep compliance C(t) = C_g + C_v (1 − e^(−t/τ_c)), the glassy compliance C_g
/// that of the elastic constants (G is the glassy, instantaneous modulus), the same for both bodies.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Visco {
    /// C_v/C_g ≥ 0 (CONTACT's FG): the relaxed modulus is G/(1 + FG).
    pub ratio: f64,
    /// The creep relaxation time τ_c [s] (CONTACT's TC); rolling at V it is the relaxation
    /// distance V τ_c (VT).
    pub time_s: f64,
}

/// CONTACT's interfacial (third-body) layer (M = 4, user guide "Interfacial layer of
/// contaminants"): sheared elastically, u = p h3 / G3, in series with the half-spaces.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Layer {
    /// The layer's shear modulus G3 [MPa] (CONTACT's GG3).
    pub g_mpa: f64,
    /// The layer's thickness h3 [mm] (CONTACT's LAYTHK).
    pub thickness_mm: f64,
    /// The layer's yield limit τ_c0 [MPa] where it flows, elastic-perfectly plastic (CONTACT's
    /// TAU_C0 with K_TAU = 0); `None`: elastic.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_mpa: Option<f64>,
    /// The rate K_TAU [MPa/mm] at which the yield limit moves with the element's accumulated
    /// plastic slip, τc = τ_c0 + K_TAU Σ|Δu_pl| (CONTACT's K_TAU; > 0 hardens, < 0 softens); 0:
    /// elastic-perfectly plastic.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub hardening_mpa_per_mm: f64,
}

impl Layer {
    /// The traction bound's pressure with the layer's yield limit: min(p, τ_c0/μ) per element, so
    /// that μ times it is CONTACT's bound min(μ pn, τ_c0) (`tangcg`, `gdsteady`: K_TAU = 0); `None`
    /// without a yield limit. Elements below the limit keep p bit for bit.
    pub fn capped_pressure(&self, mu: f64, pn_mpa: &[f64]) -> Option<Vec<f64>> {
        let cap = self.yield_mpa? / mu;
        Some(pn_mpa.iter().map(|&p| if p > cap { cap } else { p }).collect())
    }

    /// Whether the yield limit moves with the plastic slip (a yield limit and K_TAU ≠ 0).
    pub fn hardens(&self) -> bool {
        self.yield_mpa.is_some() && self.hardening_mpa_per_mm != 0.0
    }

    /// The part of an element's slip `slip_mm` [mm] in a step that is the layer's plastic flow,
    /// from the yield limit `tau_prev_mpa` [MPa] with the friction bound `friction_mpa` = μ pn
    /// (CONTACT's `plstrc`): none where μ pn ≤ τc' (the bodies slip), all of it in a softening or
    /// perfectly plastic layer, and in a hardening one no more than raises τc to μ pn.
    pub fn plastic_slip_mm(&self, tau_prev_mpa: f64, friction_mpa: f64, slip_mm: f64) -> f64 {
        let k = self.hardening_mpa_per_mm;
        if friction_mpa <= tau_prev_mpa {
            0.0
        } else if k > 0.0 {
            slip_mm.min((friction_mpa - tau_prev_mpa) / k)
        } else {
            slip_mm
        }
    }

    /// The yield limit [MPa] after the plastic slip `plastic_mm` [mm] from `tau_prev_mpa`:
    /// τc = τc' + K_TAU |Δu_pl|, not below 0.1 τ_c0 (CONTACT's `plstrc`: `taucs = taucv + k_tau
    /// dupl_abs`, `max(0.1 tau_c0, taucs)`); τ_c0 without a yield limit.
    pub fn hardened_mpa(&self, tau_prev_mpa: f64, plastic_mm: f64) -> f64 {
        let tau_c0 = self.yield_mpa.unwrap_or(f64::INFINITY);
        (tau_prev_mpa + self.hardening_mpa_per_mm * plastic_mm).max(0.1 * tau_c0)
    }

    /// The yield limit `tau_mpa` kept where the plastic slip can take it from `tau_prev_mpa`
    /// with the friction bound `friction_mpa`: up to μ pn in a hardening layer, down to
    /// 0.1 τ_c0 in a softening one ([`Layer::plastic_slip_mm`], [`Layer::hardened_mpa`]).
    pub fn reachable_mpa(&self, tau_prev_mpa: f64, friction_mpa: f64, tau_mpa: f64) -> f64 {
        let floor = 0.1 * self.yield_mpa.unwrap_or(0.0);
        if self.hardening_mpa_per_mm > 0.0 {
            tau_mpa.clamp(tau_prev_mpa, friction_mpa.max(tau_prev_mpa))
        } else {
            tau_mpa.clamp(floor.min(tau_prev_mpa), tau_prev_mpa)
        }
    }

    /// The layer's tangential flexibility h3 / G3 [mm/MPa] (CONTACT's FLX of M = 4, `m_sinput.f90`).
    pub fn flexibility_mm_per_mpa(&self) -> f64 {
        self.thickness_mm / self.g_mpa
    }
}

/// The elastic constants of each body: shear modulus [MPa] and Poisson's ratio of body 1 (the
/// upper, CONTACT's first) and body 2.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Bodies {
    pub g_mpa: [f64; 2],
    pub poisson: [f64; 2],
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

impl Material {
    /// From G and ν; E follows as `2 G (1 + ν)`.
    pub fn from_g(g_mpa: f64, poisson: f64) -> Self {
        Self {
            g_mpa,
            poisson,
            e_mpa: 2.0 * g_mpa * (1.0 + poisson),
            k: 0.0,
            bodies: None,
            layer: None,
            visco: None,
            heat: None,
            sheet_mm3_per_n: 0.0,
            blanco: None,
        }
    }

    /// From the two bodies' constants, combined as CONTACT combines them ([`combine_bodies`]),
    /// with their difference parameter K.
    pub fn from_bodies(bodies: Bodies) -> Self {
        let m = combine_bodies(bodies.poisson, bodies.g_mpa);
        Self { k: m.k, bodies: Some(bodies), ..Self::from_g(m.g_mpa, m.poisson) }
    }

    /// The interface layer's tangential flexibility h3/G3 [mm/MPa], 0 without a layer.
    pub fn layer_flexibility_mm_per_mpa(&self) -> f64 {
        self.layer.map_or(0.0, |l| l.flexibility_mm_per_mpa())
    }

    /// Whether the bodies' normal and tangential problems couple (K ≠ 0).
    pub fn coupled(&self) -> bool {
        self.k != 0.0
    }

    /// From E and ν; G follows as `E / (2 (1 + ν))`.
    pub fn from_e(e_mpa: f64, poisson: f64) -> Self {
        Self {
            g_mpa: e_mpa / (2.0 * (1.0 + poisson)),
            poisson,
            e_mpa,
            k: 0.0,
            bodies: None,
            layer: None,
            visco: None,
            heat: None,
            sheet_mm3_per_n: 0.0,
            blanco: None,
        }
    }

    /// Two-body contact modulus E* [MPa] with `1/E* = 2 (1 − ν²) / E` (two identical bodies).
    pub fn e_star_mpa(&self) -> f64 {
        self.e_mpa / (2.0 * (1.0 - self.poisson * self.poisson))
    }
}

/// Two bodies' elastic constants combined as CONTACT combines them (user guide, "Material
/// constants"; Kalker 1990 Eq. 1.19): `G = 2 G1 G2 / (G1 + G2)`, `ν = G (ν1/G1 + ν2/G2) / 2` and
/// Kalker's difference parameter `K = G/4 ((1 − 2ν1)/G1 − (1 − 2ν2)/G2)`, zero for quasi-identical
/// bodies (no coupling of the normal and tangential problems).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBodies {
    pub g_mpa: f64,
    pub poisson: f64,
    pub k: f64,
}

/// Combine the Poisson ratios and shear moduli [MPa] of bodies 1 and 2; identical bodies give
/// their own constants exactly (the formulas are the identity there).
pub fn combine_bodies(poiss: [f64; 2], gg_mpa: [f64; 2]) -> TwoBodies {
    if poiss[0] == poiss[1] && gg_mpa[0] == gg_mpa[1] {
        return TwoBodies { g_mpa: gg_mpa[0], poisson: poiss[0], k: 0.0 };
    }
    let [n1, n2] = poiss;
    let [g1, g2] = gg_mpa;
    let g = 2.0 * g1 * g2 / (g1 + g2);
    TwoBodies {
        g_mpa: g,
        poisson: g * (n1 / g1 + n2 / g2) / 2.0,
        k: g / 4.0 * ((1.0 - 2.0 * n1) / g1 - (1.0 - 2.0 * n2) / g2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_bodies_combine_as_contact_does() {
        // Identical bodies: their own constants, K = 0.
        assert_eq!(
            combine_bodies([0.28, 0.28], [82000.0, 82000.0]),
            TwoBodies { g_mpa: 82000.0, poisson: 0.28, k: 0.0 }
        );
        // Steel on a softer body (G 82000 and 20500, ν 0.28 and 0.3): G = 2·82000·20500/102500 = 32800,
        // ν = 32800 (0.28/82000 + 0.3/20500)/2 = 0.296, K = 8200 (0.44/82000 − 0.4/20500) = −0.116.
        let m = combine_bodies([0.28, 0.3], [82000.0, 20500.0]);
        assert!((m.g_mpa - 32800.0).abs() < 1e-9, "{m:?}");
        assert!((m.poisson - 0.296).abs() < 1e-12, "{m:?}");
        assert!((m.k - -0.116).abs() < 1e-12, "{m:?}");
        // Different moduli, both incompressible: K = 0 (quasi-identical).
        assert_eq!(combine_bodies([0.5, 0.5], [1000.0, 3000.0]).k, 0.0);
    }
}
