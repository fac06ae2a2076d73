//! The rolling direction CHI at any angle (`[rolling] chi_deg`, CONTACT's CHI): the contact moves
//! along `(cos CHI, sin CHI)` in CONTACT's coordinates, so in the grid's (`x = −x_C`, y the same)
//! the material moves by `dq (cos CHI, −sin CHI)` per step against it. CONTACT shifts the previous
//! state by `dq (cos CHI, sin CHI)` (`m_gridfunc.f90` `gf3_dq_shift`; `m_inflcf.f90`: previous
//! tractions at the offset `(xoffs, yoffs)`) and evaluates the spin term at the offset
//! `(cos CHI, sin CHI) FACPHI dq` (`m_sdis.f90` `set_tang_rhs`).

/// Unit vector the material moves along against the contact, grid coordinates, for CHI =
/// `chi_deg` [deg]; exact at quarter turns (CHI = 0 gives `[1, 0]`, the solver's own direction).
pub fn towards(chi_deg: f64) -> [f64; 2] {
    let turned = chi_deg.rem_euclid(360.0);
    let quarter = [[1.0, 0.0], [0.0, -1.0], [-1.0, 0.0], [0.0, 1.0]];
    if turned % 90.0 == 0.0 {
        return quarter[(turned / 90.0) as usize % 4];
    }
    let (s, c) = turned.to_radians().sin_cos();
    [c, -s]
}

#[cfg(test)]
mod tests {
    use super::towards;

    #[test]
    fn quarter_turns_are_exact_and_angles_unit_vectors() {
        assert_eq!(towards(0.0), [1.0, 0.0]);
        assert_eq!(towards(90.0), [0.0, -1.0]);
        assert_eq!(towards(-90.0), [0.0, 1.0]);
        assert_eq!(towards(540.0), [-1.0, 0.0]);
        let t = towards(30.0);
        assert!((t[0] - 0.75f64.sqrt()).abs() < 1e-15 && (t[1] + 0.5).abs() < 1e-15, "{t:?}");
    }
}
