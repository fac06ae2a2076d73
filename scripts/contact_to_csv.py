#!/usr/bin/env python3
"""CONTACT's results of a run as a reference CSV: the last leg of the round trip
`creepbench export contact` -> CONTACT (module 3) -> this script -> a reference history.

Usage:
    contact_to_csv.py EXPERIMENT.inp [--out CONTACT.out] [--csv OUT.csv]
    contact_to_csv.py --out CONTACT.out [--csv OUT.csv]

EXPERIMENT.inp is the input `creepbench export contact` wrote: its case comments give each
case's step and time, its lines the loading as CONTACT got it (FN, CKSI, CETA, CPHI, the friction,
VELOC, with every digit). The friction is Coulomb's (L = 0: the line FSTAT, FKIN) or a law falling
with the slip velocity (L = 2 linear, 3 rational, 4 exponential: the line FKIN, F1, SABSH1, F2, SABSH2,
from which CONTACT derives FSTAT = FKIN + F1 + F2, `fric_update` in `m_friclaw.f90`; see
reference/contact_friction/README.contact_friction.md, "FSTAT vs FKIN"); L = 1 keeps the previous
case's. Column `mu` is FSTAT. Each case's totals are integrated from CONTACT's per-element file
`EXPERIMENT.<case>.mat` (written because the exported input asks for it, A-digit 2; 6 significant
digits per element) or, where that file is missing, read from the totals CONTACT printed in
`EXPERIMENT.out` (4 significant digits). `--out` names the output file if it is elsewhere; given
alone (an input creepbench did not write) the loading is read from the output file too (4
digits), the step is the case number and t_s is 0.
Where both are there, each total integrated from a .mat file is compared with the one printed:
a warning names a case where they differ by more than the printed digits plus the error bound
of the elements' 6 digits (a small moment, as in a case without lateral creepage or spin, is
all rounding noise in the .mat file while CONTACT prints it from unrounded tractions).

Written: one row per case, the format of reference/contact_envelope and contact_nonhertz:
    step,t_s,cx,cy,cs,fn_n,mu,fx_n,fy_n,mz_nmm,fx_over_fn,fy_over_fn,n_adhesion,n_slip
With a falling law (L = 2, 3, 4 in any case) six columns follow, those of
reference/contact_friction:
    v_mm_s,mu_min,mu_max,s_max_mm_s,veldep_its,converged
v_mm_s the case's VELOC; mu_min, mu_max, s_max_mm_s over the elements in contact (state 1 or 2) of
the .mat file (MU, and SREL x VELOC; empty for a case read from the printed totals); veldep_its the
case's `Vel-dep:` lines in the output file (FLOW digit W = 2, as the export writes: one per
slip-velocity iteration) and converged 1 when the last one's change is within its bound (the
`.001 |Sk|` column), 0 when not (both empty without the output file).
Units N, mm, MPa (those of the exported input). Integration and signs as
reference/contact/README.contact.md and reference/contact_envelope/README.contact_envelope.md say:
element (ix, iy) has its centre at x = XL + (ix - 1/2) DX, y = YL + (iy - 1/2) DY (CONTACT's
coordinates, the potential contact's corner XL, YL from the .mat file's grid line);
    fn_n   =  sum pn dx dy
    fx_n   = -sum px dx dy,  fy_n = -sum py dx dy        (CONTACT's tractions act on body 1:
                                                          flipped, positive creepage gives a
                                                          positive coefficient)
    mz_nmm =  sum (x (-py) - y (-px)) dx dy  = -MZ as CONTACT prints it
    fx_over_fn = fx_n / fn_n,  fy_over_fn = fy_n / fn_n  (not divided by mu)
    n_adhesion, n_slip: the elements in adhesion (state 1) and in slip (state 2).
From the printed totals likewise: fn_n = FN, fx_n = -FX, fy_n = -FY, mz_nmm = -MZ,
n_adhesion = NADH, n_slip = NSLIP.

The .mat layout is CONTACT's (subroutine writmt, src/m_soutpt.f90: comment lines starting with
`%` name the columns of the line(s) that follow; the element lines follow the header
`%    I    IGS    H    MU    PN    PX    PY ...`, element I = ix + MX (iy - 1)). Python 3 standard
library only.
"""

import argparse
import csv
import io
import math
import os
import re
import sys

COLUMNS = ["step", "t_s", "cx", "cy", "cs", "fn_n", "mu", "fx_n", "fy_n", "mz_nmm",
           "fx_over_fn", "fy_over_fn", "n_adhesion", "n_slip"]
FRICTION_COLUMNS = ["v_mm_s", "mu_min", "mu_max", "s_max_mm_s", "veldep_its", "converged"]
ADHESION, SLIP = 1, 2
# CONTACT's friction laws (L digit): 0 Coulomb, 1 keep the previous case's, 2-4 falling laws.
COULOMB, KEEP, FALLING = 0, 1, (2, 3, 4)


class InputProblem(Exception):
    """Bad or missing input: exit status 2 with the message."""


def number(text):
    """A Fortran-printed number, or None."""
    try:
        return float(text)
    except ValueError:
        return None


def read_text(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()
    except OSError as e:
        raise InputProblem(f"{path}: cannot read ({e.strerror})")


# --- The exported input -------------------------------------------------------------------

CASE_COMMENT = re.compile(r"^\s*3\s+MODULE\s*%\s*step\s+(\d+),\s*t=(\S+)\s+s\s*$")


def exported_cases(path):
    """Each case of an input `creepbench export contact` wrote: step, t_s, fn_n, cx, cy, cs, mu
    = FSTAT (carried from the last case that read the friction, as CONTACT does with L = 1),
    v_mm_s (VELOC, carried likewise) and whether the friction falls with the slip velocity."""
    cases, mu, falling, veloc, law = [], None, False, None, None
    for n, line in enumerate(read_text(path).splitlines(), start=1):
        m = CASE_COMMENT.match(line)
        if m:
            cases.append({"step": int(m.group(1)), "t_s": float(m.group(2)), "mu": mu, "falling": falling,
                          "v_mm_s": veloc})
            law = None
            continue
        if re.match(r"^\s*3\s+MODULE", line):
            raise InputProblem(f"{path} line {n}: a case without the `% step k, t=... s` comment "
                               "of `creepbench export contact` (for another input give --out only)")
        label = line.split("%")[0]
        values = [number(w) for w in label.split()]
        if "FN, CKSI, CETA, CPHI" in line and cases:
            if len(values) < 4 or None in values[:4]:
                raise InputProblem(f"{path} line {n}: four numbers FN, CKSI, CETA, CPHI")
            cases[-1].update(fn_n=values[0], cx=values[1], cy=values[2], cs=values[3])
        elif "L-D-C-M-Z-E" in line and cases:
            # The control word [V]LDCMZE: L is its sixth digit from the right.
            if not values or values[0] is None or values[0] != int(values[0]) or values[0] < 0:
                raise InputProblem(f"{path} line {n}: a control word L-D-C-M-Z-E")
            law = int(values[0]) // 100000 % 10
            if law != KEEP and law != COULOMB and law not in FALLING:
                raise InputProblem(f"{path} line {n}: friction law L = {law}; this script reads L = 0 "
                                   "(Coulomb), 1 (keep) and 2, 3, 4 (falling with the slip velocity)")
        elif "FSTAT, FKIN" in line and cases:
            if law in FALLING:
                raise InputProblem(f"{path} line {n}: FSTAT, FKIN under L = {law} (a falling law reads "
                                   "FKIN, F1, SABSH1, F2, SABSH2)")
            if not values or values[0] is None:
                raise InputProblem(f"{path} line {n}: a number FSTAT")
            mu = cases[-1]["mu"] = values[0]
            falling = cases[-1]["falling"] = False
        elif "FKIN, F1, SABSH1, F2, SABSH2" in line and cases:
            if law not in FALLING:
                raise InputProblem(f"{path} line {n}: FKIN, F1, SABSH1, F2, SABSH2 under L = {law} "
                                   "(only L = 2, 3, 4 read them)")
            if len(values) < 5 or None in values[:5]:
                raise InputProblem(f"{path} line {n}: five numbers FKIN, F1, SABSH1, F2, SABSH2")
            # CONTACT's FSTAT of a falling law: its value at zero slip velocity.
            mu = cases[-1]["mu"] = values[0] + values[1] + values[3]
            falling = cases[-1]["falling"] = True
        elif "CHI, DQ, VELOC" in line and cases:
            if len(values) < 3 or values[2] is None:
                raise InputProblem(f"{path} line {n}: a number VELOC (third on the CHI, DQ, VELOC line)")
            veloc = cases[-1]["v_mm_s"] = values[2]
    if not cases:
        raise InputProblem(f"{path}: no case written by `creepbench export contact`")
    for k, c in enumerate(cases, start=1):
        if "cx" not in c or c["mu"] is None:
            raise InputProblem(f"{path}: case {k} has no FN, CKSI, CETA, CPHI line or no friction "
                               "(FSTAT, FKIN or FKIN, F1, SABSH1, F2, SABSH2) before it")
        if c["falling"] and c["v_mm_s"] is None:
            raise InputProblem(f"{path}: case {k} has a falling friction law but no CHI, DQ, VELOC before it")
    return cases


# --- CONTACT's printed output (.out) --------------------------------------------------------

def out_cases(path):
    """The values CONTACT printed per case, by column name: every line of names followed by a line
    of as many numbers (TOTAL FORCES: FN FX FY MZ ...; KINEMATIC CONSTANTS: ... CKSI CETA CPHI;
    FRICTION LAW PARAMETERS: FSTAT FKIN; CONTACT STATISTICS: NPOT NCON NADH NSLIP ...). FSTAT is
    carried into cases that keep the previous friction (it is printed only when read), and dropped
    where a case prints another friction law or friction per row. The project's reader of printed
    output, `creepbench import contact-output`, reads the same numbers (tests/all/contact_output.rs)."""
    lines = read_text(path).splitlines()
    cases, current = {}, None
    for i, line in enumerate(lines):
        m = re.match(r"^\s*Case\s+(\d+)\s*$", line)
        if m:
            previous = current
            current = int(m.group(1))
            cases[current] = {}
            if previous is not None and "FSTAT" in cases[previous]:
                cases[current]["FSTAT"] = cases[previous]["FSTAT"]
            continue
        if current is None or i + 1 >= len(lines):
            continue
        names = line.split()
        if not names or any(number(w) is not None for w in names):
            continue
        values = [number(w) for w in lines[i + 1].split()]
        if len(values) == len(names) and None not in values:
            if "FKIN" in names and names != ["FSTAT", "FKIN"]:
                # Another friction law, or friction per row (IY FSTAT FKIN): no one FSTAT.
                cases[current].pop("FSTAT", None)
                continue
            cases[current].update(zip(names, values))
    if not cases:
        raise InputProblem(f"{path}: no `Case n` in this file (is it CONTACT's output?)")
    return cases


def veldep_lines(path):
    """Per case number: the `Vel-dep:` lines CONTACT printed (FLOW digit W = 2), as the number of
    slip-velocity iterations and whether the last one's change |Sk - Sk-1| is within its bound."""
    out, case = {}, None
    for line in read_text(path).splitlines():
        m = re.match(r"^\s*Case\s+(\d+)\s*$", line)
        if m:
            case = int(m.group(1))
            continue
        if case is None or "Vel-dep:" not in line:
            continue
        values = [number(w) for w in line.rsplit(":", 1)[1].split()]
        if len(values) != 2 or None in values:
            raise InputProblem(f"{path} case {case}: a `Vel-dep:` line not ending in two numbers: {line.strip()}")
        its, _ = out.get(case, (0, 0))
        out[case] = (its + 1, int(values[0] <= values[1]))
    return out


def printed_totals(values, where):
    need = ["FN", "FX", "FY", "MZ", "NADH", "NSLIP"]
    missing = [k for k in need if k not in values]
    if missing:
        raise InputProblem(f"{where}: {', '.join(missing)} not printed (OUTPUT digit >= 2 prints them)")
    return {"fn_n": values["FN"], "fx_n": -values["FX"], "fy_n": -values["FY"], "mz_nmm": -values["MZ"],
            "n_adhesion": int(values["NADH"]), "n_slip": int(values["NSLIP"])}


# --- CONTACT's per-element output (.mat) ----------------------------------------------------

def rounding(v):
    """Half a unit in the last place of `v` as the .mat file prints it (6 significant digits)."""
    return 0.0 if v == 0.0 else 0.5 * 10 ** (math.floor(math.log10(abs(v))) - 5)


def mat_file(path):
    """A .mat file's grid line, friction line (`%    L    H      VELOC ...`) and element lines, each
    as a dict by its `%` header's column names."""
    header, grid, friction, elements = None, None, None, []
    for n, line in enumerate(read_text(path).splitlines(), start=1):
        if line.lstrip().startswith("%"):
            header = line.lstrip().lstrip("%").split()
            continue
        if not line.strip():
            continue
        values = [number(w) for w in line.split()]
        if header is None or None in values:
            raise InputProblem(f"{path} line {n}: numbers under a `%` header line")
        if header[:2] == ["I", "IGS"]:
            elements.append(dict(zip(header, values)))
        elif header[:2] == ["MX", "MY"]:
            grid = dict(zip(header, values))
        elif header[:3] == ["L", "H", "VELOC"]:
            friction = dict(zip(header, values))
    if grid is None:
        raise InputProblem(f"{path}: no grid line (`%   MX    MY    XL ...`)")
    return grid, friction, elements


def mat_friction(path, veloc):
    """mu_min, mu_max and the largest slip velocity s = SREL x VELOC [mm/s] over the elements in
    contact (state 1 or 2) of one .mat file; VELOC from its friction line, else `veloc`."""
    _, friction, elements = mat_file(path)
    v = friction["VELOC"] if friction and "VELOC" in friction else veloc
    inside = [e for e in elements if int(e["IGS"]) in (ADHESION, SLIP)]
    if not inside or "MU" not in inside[0] or "SREL" not in inside[0]:
        raise InputProblem(f"{path}: no element in contact with MU and SREL columns")
    mus = [e["MU"] for e in inside]
    return min(mus), max(mus), max(e["SREL"] * v for e in inside)


def mat_totals(path):
    """Totals of one .mat file, integrated over its elements (see the module's doc), and a bound
    on each total's error from the elements' printed digits (`rounding` of PN, PX, PY carried
    through the sums): where a total is small, such as mz of a case without lateral creepage or
    spin (about 0.03 N mm on 600 elements of 400 MPa), that bound exceeds the total itself."""
    grid, _, elements = mat_file(path)
    mx, my = int(grid["MX"]), int(grid["MY"])
    xl, yl, dx, dy = grid["XL"], grid["YL"], grid["DX"], grid["DY"]
    t = {"fn_n": 0.0, "fx_n": 0.0, "fy_n": 0.0, "mz_nmm": 0.0, "n_adhesion": 0, "n_slip": 0}
    noise = {"fn_n": 0.0, "fx_n": 0.0, "fy_n": 0.0, "mz_nmm": 0.0}
    for e in elements:
        i = int(e["I"]) - 1
        ix, iy = i % mx + 1, i // mx + 1
        if iy > my:
            raise InputProblem(f"{path}: element {i + 1} outside the {mx} x {my} grid")
        x, y = xl + (ix - 0.5) * dx, yl + (iy - 0.5) * dy
        px, py = -e["PX"], -e["PY"]  # flipped: the tractions on body 2
        t["fn_n"] += e["PN"] * dx * dy
        t["fx_n"] += px * dx * dy
        t["fy_n"] += py * dx * dy
        t["mz_nmm"] += (x * py - y * px) * dx * dy
        ex, ey = rounding(px), rounding(py)
        noise["fn_n"] += rounding(e["PN"]) * dx * dy
        noise["fx_n"] += ex * dx * dy
        noise["fy_n"] += ey * dx * dy
        noise["mz_nmm"] += (abs(x) * ey + abs(y) * ex) * dx * dy
        t["n_adhesion"] += int(e["IGS"]) == ADHESION
        t["n_slip"] += int(e["IGS"]) == SLIP
    return t, noise


def agrees_to_print(ours, printed, noise):
    """`ours`, integrated from digits with error at most `noise`, rounds to `printed`, a value
    CONTACT printed with 4 significant digits (from its unrounded tractions)."""
    if printed == 0.0:
        return True  # CONTACT prints values dominated by noise as 0 (filt_sml)
    half_unit = 0.5 * 10 ** (math.floor(math.log10(abs(printed))) - 3)
    return abs(ours - printed) <= 1.01 * half_unit + noise


# --- The table ------------------------------------------------------------------------------

def rows(inp, out):
    printed = out_cases(out) if out and os.path.isfile(out) else {}
    if out and not printed and not inp:
        raise InputProblem(f"{out}: not found")
    if inp:
        loading = exported_cases(inp)
        experiment = inp[:-len(".inp")] if inp.endswith(".inp") else inp
    else:
        loading = []
        for k in sorted(printed):
            v = printed[k]
            missing = [n for n in ("CKSI", "CETA", "CPHI", "FSTAT") if n not in v]
            if missing:
                raise InputProblem(f"{out} case {k}: {', '.join(missing)} not printed")
            loading.append({"step": k, "t_s": 0.0, "fn_n": v.get("FN"), "cx": v["CKSI"], "cy": v["CETA"],
                            "cs": v["CPHI"], "mu": v["FSTAT"]})
        experiment = None
    falling = any(c.get("falling") for c in loading)
    veldep = veldep_lines(out) if falling and out and os.path.isfile(out) else {}
    out_rows, from_mat, mismatches = [], 0, []
    for case, load in enumerate(loading, start=1):
        mat = f"{experiment}.{case:04d}.mat" if experiment else None
        if mat and os.path.isfile(mat):
            totals, noise = mat_totals(mat)
            from_mat += 1
            if case in printed:
                p = printed_totals(printed[case], f"{out} case {case}")
                for key in ("fn_n", "fx_n", "fy_n", "mz_nmm"):
                    if not agrees_to_print(totals[key], p[key], noise[key]):
                        mismatches.append(f"case {case} {key}: {totals[key]:.7g} from {mat} (digits: +-{noise[key]:.2g}), "
                                          f"{p[key]:.4g} printed")
        elif case in printed:
            totals = printed_totals(printed[case], f"{out} case {case}")
        else:
            raise InputProblem(f"case {case}: neither {mat or 'a .mat file'} nor its totals in {out or 'an output file'}")
        row = dict(load)
        row.update(totals)
        row["fx_over_fn"] = totals["fx_n"] / totals["fn_n"]
        row["fy_over_fn"] = totals["fy_n"] / totals["fn_n"]
        if falling:
            mu_min = mu_max = s_max = None
            if mat and os.path.isfile(mat):
                mu_min, mu_max, s_max = mat_friction(mat, load["v_mm_s"])
            its, converged = veldep.get(case, (None, None))
            row.update(mu_min=mu_min, mu_max=mu_max, s_max_mm_s=s_max, veldep_its=its, converged=converged)
        out_rows.append(row)
    extra = set(printed) - set(range(1, len(loading) + 1))
    if extra:
        raise InputProblem(f"{out}: cases {sorted(extra)} beyond the input's {len(loading)}")
    print(f"{len(out_rows)} cases: {from_mat} from .mat files, {len(out_rows) - from_mat} from the printed "
          "totals", file=sys.stderr)
    for m in mismatches:
        print(f"warning: {m}", file=sys.stderr)
    return out_rows


def fmt(key, value):
    if value is None:
        return ""
    if key in ("step", "n_adhesion", "n_slip", "veldep_its", "converged"):
        return str(int(value))
    if key in ("t_s", "cx", "cy", "cs", "mu", "v_mm_s"):
        return repr(float(value))  # the loading as CONTACT got it, every digit
    return f"{value:.7g}"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("input", nargs="?", help="the input `creepbench export contact` wrote (EXPERIMENT.inp)")
    ap.add_argument("--out", help="CONTACT's output file (default EXPERIMENT.out)")
    ap.add_argument("--csv", help="the reference CSV to write (default: standard output)")
    a = ap.parse_args(argv)
    if not a.input and not a.out:
        ap.error("give the exported input, CONTACT's output file (--out), or both")
    out = a.out
    if a.input and not out:
        out = (a.input[:-len(".inp")] if a.input.endswith(".inp") else a.input) + ".out"
    try:
        table = rows(a.input, out)
    except InputProblem as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    columns = COLUMNS + (FRICTION_COLUMNS if any(r.get("falling") for r in table) else [])
    text = io.StringIO()
    w = csv.writer(text, lineterminator="\n")
    w.writerow(columns)
    for r in table:
        w.writerow([fmt(k, r[k]) for k in columns])
    if not a.csv:
        sys.stdout.write(text.getvalue())
        return 0
    # Written whole: a temporary file beside the target, then one rename.
    tmp = f"{a.csv}.{os.getpid()}.tmp"
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        f.write(text.getvalue())
    os.replace(tmp, a.csv)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
