#!/usr/bin/env python3
"""CONTACT's results of a run as a reference CSV: the last leg of the round trip
`creepbench export contact` -> CONTACT (module 3) -> this script -> a reference history.

Usage:
    contact_to_csv.py EXPERIMENT.inp [--out CONTACT.out] [--csv OUT.csv]
    contact_to_csv.py --out CONTACT.out [--csv OUT.csv]

EXPERIMENT.inp is the input `creepbench export contact` wrote: its case comments give each
case's step and time, its lines the loading as CONTACT got it (FN, CKSI, CETA, CPHI, FSTAT, with
every digit). Each case's totals are integrated from CONTACT's per-element file
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
ADHESION, SLIP = 1, 2


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
    (mu carried from the last case that read FSTAT, as CONTACT does with L = 1)."""
    cases, mu = [], None
    for n, line in enumerate(read_text(path).splitlines(), start=1):
        m = CASE_COMMENT.match(line)
        if m:
            cases.append({"step": int(m.group(1)), "t_s": float(m.group(2)), "mu": mu})
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
        elif "FSTAT, FKIN" in line and cases:
            if not values or values[0] is None:
                raise InputProblem(f"{path} line {n}: a number FSTAT")
            mu = cases[-1]["mu"] = values[0]
    if not cases:
        raise InputProblem(f"{path}: no case written by `creepbench export contact`")
    for k, c in enumerate(cases, start=1):
        if "cx" not in c or c["mu"] is None:
            raise InputProblem(f"{path}: case {k} has no FN, CKSI, CETA, CPHI line or no FSTAT before it")
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


def mat_totals(path):
    """Totals of one .mat file, integrated over its elements (see the module's doc), and a bound
    on each total's error from the elements' printed digits (`rounding` of PN, PX, PY carried
    through the sums): where a total is small, such as mz of a case without lateral creepage or
    spin (about 0.03 N mm on 600 elements of 400 MPa), that bound exceeds the total itself."""
    header, grid, elements = None, None, []
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
    if grid is None:
        raise InputProblem(f"{path}: no grid line (`%   MX    MY    XL ...`)")
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
    if key in ("step", "n_adhesion", "n_slip"):
        return str(int(value))
    if key in ("t_s", "cx", "cy", "cs", "mu"):
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
    text = io.StringIO()
    w = csv.writer(text, lineterminator="\n")
    w.writerow(COLUMNS)
    for r in table:
        w.writerow([fmt(k, r[k]) for k in COLUMNS])
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
