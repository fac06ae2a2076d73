//! A number as CONTACT printed it, with the resolution of its printed digits.

/// A printed value and half a unit of its last printed digit: the bound of the rounding that
/// printing did (Fortran's F and E edit descriptors round to nearest).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Printed {
    pub value: f64,
    /// Half a unit of the last printed digit, in the value's unit ("0.8750" → 5e-5).
    pub half_unit: f64,
}

impl Printed {
    /// A printed number, or None for a token that is not one (a label, `*****`).
    pub fn parse(text: &str) -> Option<Printed> {
        let value: f64 = text.parse().ok()?;
        let half_unit = half_unit(text)?;
        value.is_finite().then_some(Printed { value, half_unit })
    }

    /// The same number with the other sign (CONTACT's body 1 → this project's body 2).
    pub fn negated(self) -> Printed {
        Printed { value: -self.value, ..self }
    }

    /// `self / other` with the first-order bound of both roundings:
    /// |Δ(a/b)| ≤ (Δa + |a/b| Δb) / |b|.
    pub fn over(self, other: Printed) -> Printed {
        let value = self.value / other.value;
        Printed { value, half_unit: (self.half_unit + value.abs() * other.half_unit) / other.value.abs() }
    }

    /// `self × k` for an exact factor `k`.
    pub fn times(self, k: f64) -> Printed {
        Printed { value: self.value * k, half_unit: self.half_unit * k.abs() }
    }
}

/// Half a unit of the last digit `text` prints: 0.5 × 10^(exponent − digits after the point)
/// ("0.8750" → 5e-5, "1.998E-02" → 5e-6, "1722." → 0.5, "361" → 0.5); None if `text` is not a
/// plain decimal number (digits, one optional point, an optional E/D exponent).
pub fn half_unit(text: &str) -> Option<f64> {
    let body = text.strip_prefix(['-', '+']).unwrap_or(text);
    let (mantissa, exponent) = match body.find(['E', 'e', 'D', 'd']) {
        Some(k) => (&body[..k], body[k + 1..].parse::<i32>().ok()?),
        None => (body, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if whole.len() + fraction.len() == 0 || !digits(whole) || !digits(fraction) {
        return None;
    }
    Some(0.5 * 10f64.powi(exponent - fraction.len() as i32))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_a_unit_of_the_last_printed_digit() {
        let close = |t: &str, want: f64| {
            let got = half_unit(t).unwrap();
            assert!((got - want).abs() <= 1e-12 * want, "{t}: {got} != {want}");
        };
        close("0.8750", 5e-5);
        close("-0.8750", 5e-5);
        close("1.998E-02", 5e-6);
        close("0.1000E-03", 5e-8);
        close("4.000E+05", 50.0);
        close("1722.", 0.5);
        close("361", 0.5);
        close("2.84688", 5e-6);
        close("0.000", 5e-4);
        for bad in ["", ".", "FN", "1.2.3", "1.0E", "*****", "1e5x"] {
            assert_eq!(half_unit(bad), None, "{bad:?}");
        }
    }

    #[test]
    fn a_ratio_carries_both_roundings() {
        let fx = Printed::parse("-3.218").unwrap();
        let fn_ = Printed::parse("9.195").unwrap();
        let r = fx.negated().over(fn_);
        assert!((r.value - 3.218 / 9.195).abs() < 1e-15);
        // (5e-4 + 0.35 · 5e-4) / 9.195
        assert!((r.half_unit - (5e-4 + r.value * 5e-4) / 9.195).abs() < 1e-18);
        assert_eq!(Printed::parse("NaN"), None);
        assert_eq!(Printed::parse("inf"), None);
    }
}
