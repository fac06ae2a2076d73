#!/usr/bin/env python3
"""Write scenes/friction_hidden/<case>.toml (and the creepage tables of the speed ramps): the
falling-friction cases of reference/contact_friction_hidden, new against every case of
reference/contact_friction and reference/contact_friction_variants (other law parameters, memories,
speeds, loadings, ellipses and grids). Each case's CONTACT input is this scene's
`creepbench export contact`; see reference/contact_friction_hidden/README.md. Run from the
repository root:
    python3 scripts/make_hidden_friction_scenes.py
"""
import os

OUT = "scenes/friction_hidden"

# The laws: (law, fkin, f1, sabsh1, f2, sabsh2); FSTAT = fkin + f1 + f2.
LIN_A = ("linear", 0.16, 0.26, 700.0, 0.0, 0.0)  # FSTAT 0.42
LIN2_B = ("linear", 0.20, 0.10, 350.0, 0.10, 1800.0)  # FSTAT 0.40
RAT_A = ("rational", 0.21, 0.19, 500.0, 0.0, 0.0)  # FSTAT 0.40
RAT2_B = ("rational", 0.19, 0.14, 300.0, 0.09, 3500.0)  # FSTAT 0.42
EXP_A = ("exponential", 0.23, 0.21, 450.0, 0.0, 0.0)  # FSTAT 0.44
EXP2_B = ("exponential", 0.17, 0.15, 350.0, 0.10, 2200.0)  # FSTAT 0.42

THESIS = (8.56, 4.08, 100000.0)


def friction(law, memory):
    name, fkin, f1, s1, f2, s2 = law
    lines = ["[friction]", f'law = "{name}"', f"fkin = {fkin!r}", f"f1 = {f1!r}", f"sabsh1_mm_s = {s1!r}"]
    if f2 > 0.0:
        lines += [f"f2 = {f2!r}", f"sabsh2_mm_s = {s2!r}"]
    if memory:
        lines += [f"memory_mm = {memory[0]!r}", f"memory_s0_mm_s = {memory[1]!r}"]
    return "\n".join(lines)


def scene(name, note, law, memory, v, creepage, init=None, contact=THESIS, grid=(22, 22, 1.0), courant=1.0):
    a, b, fn = contact
    mx, my, scale = grid
    text = f"""# Hidden case {name} of reference/contact_friction_hidden (its {name}.inp is this scene's `creepbench export contact`).
# {note}

name = "{name}"
solvers = ["contact"]

[contact]
a_mm = {a!r}
b_mm = {b!r}
fn_n = {fn!r}

{friction(law, memory)}

[material]
g_mpa = 82000.0
poisson = 0.28

[grid]
mx = {mx}
my = {my}
scale = {scale!r}

[rolling]
v_mm_s = {v!r}
courant = {courant!r}

[creepage]
{creepage.strip()}
"""
    if init:
        text += f'\n[init]\nkind = "{init}"\n'
    with open(os.path.join(OUT, name + ".toml"), "w") as f:
        f.write(text)


def speed_table(name, dq, rows):
    """rows: (cx, v_mm_s) of steps 0, 1, ...; t_k = t_(k-1) + dq / v_k as CONTACT steps."""
    t, lines = 0.0, ["t_s,cx,v_mm_s"]
    for k, (cx, v) in enumerate(rows):
        if k > 0:
            t += dq / v
        lines.append(f"{t!r},{cx!r},{v!r}")
    with open(os.path.join(OUT, name + "_table.csv"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return f'kind = "table"\nfile = "{name}_table.csv"'


def main():
    os.makedirs(OUT, exist_ok=True)
    dx = 2 * 8.56 / 22

    # Steady traction curves through the peak into the falling branch.
    scene("h01_lin_sweep_cx_v18", "LIN (fkin .16 f1 .26 s1 700), steady cx sweep 0.0005 .. 0.08 at V 18 m/s, no memory: "
          "through the peak, on to FKIN beyond s = 1.4 m/s.", LIN_A, None, 18000.0,
          'kind = "sweep"\nat = [0.0005, 0.0015, 0.0025, 0.0035, 0.0045, 0.0055, 0.0065, 0.0075, 0.009, 0.012, '
          '0.016, 0.022, 0.03, 0.045, 0.06, 0.08]')
    scene("h02_rat2_sweep_cy_spin", "RAT two terms (fkin .19 f1 .14 s1 300 f2 .09 s2 3500), steady cy sweep 0 .. 0.03 at "
          "cx 0.0005, cs 0.0004/mm, V 28 m/s, no memory.", RAT2_B, None, 28000.0,
          'kind = "sweep"\nover = "cy"\nat = [0.0, 0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.008, 0.011, 0.015, '
          '0.02, 0.03]\ncx = 0.0005\ncs = 0.0004')
    scene("h03_exp_sweep_spin_mem", "EXP (fkin .23 f1 .21 s1 450), steady spin sweep 0 .. 0.012/mm at cx 0.001, V 22 m/s, "
          "memory d_c 0.007 s0 8.", EXP_A, (0.007, 8.0), 22000.0,
          'kind = "sweep"\nover = "cs"\nat = [0.0, 0.0008, 0.0016, 0.0025, 0.004, 0.006, 0.009, 0.012]\ncx = 0.001')
    scene("h04_lin2_sweep_combined_mem", "LIN two terms (fkin .2 f1 .1 s1 350 f2 .1 s2 1800), steady sweep along "
          "(cx, cy) = t (1, 0.5), t 0.0008 .. 0.024, cs -0.0002, V 33 m/s, memory d_c 0.012 s0 4.", LIN2_B,
          (0.012, 4.0), 33000.0,
          'kind = "sweep"\ndirection = [1.0, 0.5, 0.0]\nat = [0.0008, 0.0016, 0.0024, 0.0032, 0.004, 0.0052, 0.0064, '
          '0.0088, 0.012, 0.016, 0.024]\ncs = -0.0002')
    scene("h05_exp2_speed_sweep_mem", "EXP two terms (fkin .17 f1 .15 s1 350 f2 .1 s2 2200), steady VELOC sweep 7 .. 52 "
          "m/s at cx 0.007, cy -0.001, memory d_c 0.004 s0 12.", EXP2_B, (0.004, 12.0), 7000.0,
          'kind = "sweep"\nover = "v_mm_s"\nat = [7000.0, 12000.0, 18000.0, 26000.0, 35000.0, 44000.0, 52000.0]\n'
          'cx = 0.007\ncy = -0.001')
    scene("h06_rat_slender_sweep_cx_mem", "RAT (fkin .21 f1 .19 s1 500), slender ellipse a 10 b 3 mm (b/a 0.3), FN 70 kN, "
          "grid 26 x 14, steady cx sweep 0.001 .. 0.025, V 26 m/s, memory d_c 0.009 s0 6.", RAT_A, (0.009, 6.0),
          26000.0, 'kind = "sweep"\nat = [0.001, 0.002, 0.003, 0.004, 0.005, 0.0065, 0.008, 0.011, 0.016, 0.025]',
          contact=(10.0, 3.0, 70000.0), grid=(26, 14, 1.0))
    scene("h07_rat2_coarse_sweep_cx_cy", "RAT two terms, coarse grid 14 x 12, steady cx sweep 0.0005 .. 0.03 at cy 0.0015, "
          "V 40 m/s, no memory.", RAT2_B, None, 40000.0,
          'kind = "sweep"\nat = [0.0005, 0.0015, 0.0025, 0.0035, 0.005, 0.007, 0.01, 0.015, 0.022, 0.03]\ncy = 0.0015',
          grid=(14, 12, 1.0))

    # Transient: steps from zero, a step down from a steady state, sines, speed ramps.
    scene("h08_lin_step_low_nomem", "LIN (fkin .16 f1 .26 s1 700), step cx 0.0025 cy -0.0012 from zero below the peak "
          "(partial slip), V 24 m/s, no memory, 44 steps.", LIN_A, None, 24000.0,
          'kind = "step"\nc = 0.0025\ncy = -0.0012\nsteps = 44', init="zero")
    scene("h09_exp2_step_falling_spin_mem", "EXP two terms, step cx 0.011 cs 0.0003 from zero into the falling branch, V 35 "
          "m/s, memory d_c 0.015 s0 5, 60 steps.", EXP2_B, (0.015, 5.0), 35000.0,
          'kind = "step"\nc = 0.011\ncs = 0.0003\nsteps = 60', init="zero")
    scene("h10_rat2_step_cy_mem", "RAT two terms, pure lateral step cy 0.009 from zero, V 16 m/s, memory d_c 0.025 s0 3, "
          "50 steps.", RAT2_B, (0.025, 3.0), 16000.0,
          'kind = "step"\nc = 0.0\ncy = 0.009\nsteps = 50', init="zero")
    scene("h11_exp_stepdown_steady_mem", "EXP (fkin .23 f1 .21 s1 450), step down from a steady cx 0.012 (falling branch) "
          "to 0.004, V 27 m/s, memory d_c 0.006 s0 15, 44 steps.", EXP_A, (0.006, 15.0), 27000.0,
          'kind = "step"\nc_before = 0.012\nc = 0.004\nsteps = 44', init="steady")
    scene("h12_lin2_sine_through_zero_mem", "LIN two terms, cx = 0.004 + 0.006 sin(2 pi 350 t) (through zero and into "
          "the falling branch), cy 0.001, V 21 m/s, memory d_c 0.01 s0 10, steady start, 1.25 periods.", LIN2_B,
          (0.01, 10.0), 21000.0,
          'kind = "sine"\nc0 = 0.004\ncp = 0.006\nfreq_hz = 350.0\nperiods = 1.25\ncy = 0.001', init="steady")
    scene("h13_rat_sine_low_nomem", "RAT (fkin .21 f1 .19 s1 500), cx = 0.0022 + 0.0012 sin(2 pi 200 t) below the peak, "
          "V 14 m/s, no memory, steady start, 1 period.", RAT_A, None, 14000.0,
          'kind = "sine"\nc0 = 0.0022\ncp = 0.0012\nfreq_hz = 200.0\nperiods = 1.0', init="steady")
    dq = dx
    ramp = [(0.005 + 0.004 * min(k, 30) / 30, 8000.0 + 24000.0 * min(k, 30) / 30) for k in range(46)]
    scene("h14_rat2_speed_ramp_cx_ramp_mem", "RAT two terms, VELOC 8 -> 32 m/s and cx 0.005 -> 0.009 together over 30 "
          "steps, then held 15, steady start, memory d_c 0.008 s0 7.", RAT2_B, (0.008, 7.0), 8000.0,
          speed_table("h14_rat2_speed_ramp_cx_ramp_mem", dq, ramp), init="steady")
    updown = [(0.007, 20000.0 + 24000.0 * (k / 20 if k <= 20 else max(0.0, (40 - k) / 20))) for k in range(51)]
    scene("h15_lin_speed_updown_mem", "LIN (fkin .16 f1 .26 s1 700), VELOC 20 -> 44 -> 20 m/s over 20 + 20 steps, then "
          "held 10, cx 0.007 cy 0.002 held, steady start, memory d_c 0.02 s0 10.", LIN_A, (0.02, 10.0), 20000.0,
          speed_table("h15_lin_speed_updown_mem", dq, updown) + "\ncy = 0.002", init="steady")
    scene("h16_exp_fine_grid_step_mem", "EXP (fkin .23 f1 .21 s1 450), fine grid 32 x 30, step cx 0.009 cy 0.001 from "
          "zero, V 32 m/s, memory d_c 0.004 s0 10, 64 steps: full slip from step 12, then a period-2 oscillation that does not decay (tight values alternate 0.3711 / 0.3597 from step ~25 to the end; CONTACT's 1e-3 stop leaves up to 1.8e-3 in it).", EXP_A, (0.004, 10.0), 32000.0,
          'kind = "step"\nc = 0.009\ncy = 0.001\nsteps = 64', init="zero", grid=(32, 30, 1.0))
    scene("h19_exp_fine_grid_step_mem_dc008", "EXP (fkin .23 f1 .21 s1 450), fine grid 32 x 30, step cx 0.009 cy 0.001 "
          "from zero, V 32 m/s, memory d_c 0.008 s0 10 (h16 with twice its memory: one overshoot, then it settles), "
          "48 steps.", EXP_A, (0.008, 10.0), 32000.0,
          'kind = "step"\nc = 0.009\ncy = 0.001\nsteps = 48', init="zero", grid=(32, 30, 1.0))
    scene("h17_lin2_courant075_step_spin_mem", "LIN two terms, Courant 0.75, step cx 0.006 cs 0.0008 from zero, V 38 m/s, "
          "memory d_c 0.006 s0 6, 50 steps.", LIN2_B, (0.006, 6.0), 38000.0,
          'kind = "step"\nc = 0.006\ncs = 0.0008\nsteps = 50', init="zero", courant=0.75)
    scene("h18_exp2_wide_step_cy_cx_mem", "EXP two terms, wide ellipse a 6 b 7.5 mm (b/a 1.25), FN 80 kN, grid 20 x 24, step "
          "cx 0.004 cy 0.005 from zero, V 45 m/s, memory d_c 0.01 s0 20, 40 steps.", EXP2_B, (0.01, 20.0), 45000.0,
          'kind = "step"\nc = 0.004\ncy = 0.005\nsteps = 40', init="zero", contact=(6.0, 7.5, 80000.0),
          grid=(20, 24, 1.0))


if __name__ == "__main__":
    main()
