//! Axis titles for scene keys and metric names: a name with its unit (`creepage.freq_hz` →
//! `frequency [Hz]`, `delay_ratio` → `delay ratio [–]`), never the raw key.

/// Known keys and metrics with their titles.
const KNOWN: [(&str, &str); 24] = [
    ("t_s", "t [s]"),
    ("v_mm_s", "V [mm/s]"),
    ("cx", "creepage c_x [–]"),
    ("cy", "creepage c_y [–]"),
    ("cs", "spin creepage c_s [1/mm]"),
    ("fx_over_fn", "f_x / F_N [–]"),
    ("fy_over_fn", "f_y / F_N [–]"),
    ("mz_over_fn_a", "m_z / (F_N a) [–]"),
    ("creepage.freq_hz", "frequency [Hz]"),
    ("creepage.c0", "mean creepage c₀ [–]"),
    ("creepage.cp", "creepage amplitude c_p [–]"),
    ("contact.mu", "friction coefficient μ [–]"),
    ("contact.fn_n", "normal force F_N [N]"),
    ("contact.a_mm", "semi-axis a [mm]"),
    ("contact.b_mm", "semi-axis b [mm]"),
    ("grid.mx", "elements along x [–]"),
    ("grid.my", "elements along y [–]"),
    ("angle", "creepage direction [°]"),
    ("delay_ratio", "delay ratio [–]"),
    ("loop_area", "loop area [–]"),
    ("steady_value", "steady f = F/F_N [–]"),
    ("settling_time_s", "settling time [s]"),
    ("oscillation_index", "oscillation index [–]"),
    ("sawtooth_index", "sawtooth index [–]"),
];

/// Unit suffixes of scene keys (README: units in names) and how a title writes them.
const UNITS: [(&str, &str); 9] = [
    ("_hz", "Hz"),
    ("_s", "s"),
    ("_mm", "mm"),
    ("_n", "N"),
    ("_mpa", "MPa"),
    ("_deg", "°"),
    ("_rad", "rad"),
    ("_nmm", "N·mm"),
    ("_m", "m"),
];

/// The title of a key or metric: a known one's, else its last part with the unit its suffix
/// names (dimensionless `[–]` without one), underscores as spaces.
pub fn of(key: &str) -> String {
    if let Some((_, t)) = KNOWN.iter().find(|(k, _)| *k == key) {
        return (*t).to_string();
    }
    let last = key.rsplit('.').next().unwrap_or(key);
    let (stem, unit) = UNITS
        .iter()
        .filter_map(|(suffix, unit)| last.strip_suffix(suffix).filter(|s| !s.is_empty()).map(|s| (s, *unit)))
        .max_by_key(|(s, _)| std::cmp::Reverse(s.len()))
        .unwrap_or((last, "–"));
    format!("{} [{unit}]", stem.replace('_', " "))
}

#[cfg(test)]
mod tests {
    #[test]
    fn keys_become_names_with_units() {
        assert_eq!(super::of("creepage.freq_hz"), "frequency [Hz]");
        assert_eq!(super::of("delay_ratio"), "delay ratio [–]");
        assert_eq!(super::of("material.g_mpa"), "g [MPa]");
        assert_eq!(super::of("peak_moment_nmm"), "peak moment [N·mm]");
        assert_eq!(super::of("rise_time_s"), "rise time [s]");
        assert_eq!(super::of("my_index"), "my index [–]");
    }
}
