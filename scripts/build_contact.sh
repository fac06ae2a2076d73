#!/usr/bin/env bash
# Build CONTACT (github.com/eve70a/CONTACT, Apache-2.0) from source with gfortran, without Intel's
# compiler or MKL, to time it beside creepbench (docs/wheelrail.md, "Speed") or to run a deck.
#
#   scripts/build_contact.sh SRC [OUT]
#
# SRC: a checkout of the CONTACT repository, or a bare git copy of it (its src/ is taken from HEAD).
# OUT: where the build goes (default /tmp/contact-build); the program is OUT/contact_linux64.
# Run a deck NAME.inp with `OUT/contact_linux64 2 NAME` in a scratch copy of its folder (CONTACT
# writes its output files next to the deck).
#
# Needs gfortran, LAPACK and BLAS (Debian/Ubuntu: gfortran liblapack-dev
# libblas-dev). CONTACT is written for Intel Fortran; a handful of lines that gfortran rejects are
# changed in the copy (none in the solvers): a function declared without parentheses, a CLOSE
# option, a folder scan (replaced by one finding nothing), logical comparisons written with .ne.,
# a name declared twice, a component reached without its parent, integer flags used as logicals,
# and a test routine made private. The modules are compiled in dependency order by retrying those
# whose modules are not yet built.
set -euo pipefail

src=${1:?usage: scripts/build_contact.sh SRC [OUT]}
out=${2:-/tmp/contact-build}
mkdir -p "$out/obj" "$out/src"

# The sources, from a work tree or from a bare repository's HEAD.
if [ -d "$src/src" ]; then
    cp "$src"/src/*.* "$out/src/"
else
    # File by file: a mirror may lack the repository's large files, which `git archive` refuses.
    for f in $(git -C "$src" ls-tree HEAD src/ | awk '$2 == "blob" { print $4 }'); do
        git -C "$src" show "HEAD:$f" >"$out/src/${f#src/}"
    done
fi
cd "$out/src"

# The gfortran edits; each must find its text, so a changed upstream source stops the build.
python3 - <<'EDITS'
import re

def edit(path, old, new, regex=False):
    text = open(path).read()
    found = re.search(old, text) if regex else (old in text)
    if not found:
        raise SystemExit(f"{path}: expected text not found: {old[:60]!r}")
    text = re.sub(old, new, text, count=1) if regex else text.replace(old, new)
    open(path, "w").write(text)

edit("m_licensing.f90", "\nfunction LicenseGetDebug\n", "\nfunction LicenseGetDebug()\n")
edit("m_licensing.f90", "dispose='delete', ", "")
# ScanFolder uses Intel's directory routines: a stand-in that finds no file.
text = open("m_licensing.f90").read()
start = text.index("subroutine ScanFolder(")
end = text.index("end subroutine ScanFolder", start)
stub = (
    "subroutine ScanFolder(folder, pattern, nfound, fullname, idebug)\n"
    "   implicit none\n"
    "   character(len=*), intent(in)  :: folder, pattern\n"
    "   character(len=*), intent(out) :: fullname\n"
    "   integer,          intent(in)  :: idebug\n"
    "   integer,          intent(out) :: nfound\n"
    "   nfound = 0\n"
    "   fullname = ' '\n"
)
open("m_licensing.f90", "w").write(text[:start] + stub + text[end:])
for a, b in [("iu0,1:nmeasv", "iu1+1,1:nmeasv"), ("1:nmeasu,j0", "1:nmeasu,j1+1")]:
    edit("m_bspline_make.f90", f"mask({a}).ne.mask({b})", f"mask({a}).neqv.mask({b})")
edit("m_gridfunc.f90", r"\n\s*private\s+strlen\s*\n", "\n", regex=True)
edit("m_gridfunc.f90", r"\n\s*integer,\s*parameter\s*::\s*strlen\s*=\s*16\s*\n", "\n", regex=True)
edit("m_temperature.f90", "row1st => igs%row1st,   rowlst => igs%rowlst",
     "row1st => outpt%igs%row1st,   rowlst => outpt%igs%rowlst")
edit("m_snorm.f90", "public  test_fft", "! public  test_fft")
edit("m_varprof.f90", "      if (is_wheel) then\n         x_nam = 'th'",
     "      if (is_wheel.ne.0) then\n         x_nam = 'th'")
edit("m_wr_output.f90", "               if (is_right) then\n                  ii = j",
     "               if (is_right.ne.0) then\n                  ii = j")
EDITS

flags=(-cpp -O2 -ffree-line-length-none -fPIC -DTARGET_exe -w -fdec-format-defaults -fallow-argument-mismatch)
obj="$out/obj"
pending=$(ls m_*.f90 mkl_dfti.f90 | grep -v '^m_caddon_data')
for _ in $(seq 1 40); do
    failed=""
    for f in $pending; do
        extra=()
        [ "$f" = m_readline.f90 ] && extra=(-fbackslash)
        gfortran "${flags[@]}" "${extra[@]}" -J"$obj" -I"$obj" -c "$f" -o "$obj/${f%.f90}.o" \
            2>"$obj/${f%.f90}.log" || failed="$failed $f"
    done
    pending=$failed
    [ -z "$pending" ] && break
done
if [ -n "$pending" ]; then
    echo "not compiled:$pending (see $obj/*.log)" >&2
    exit 1
fi
gfortran "${flags[@]}" -J"$obj" -I"$obj" contact.f90 "$obj"/*.o -o "$out/contact_linux64" -llapack -lblas
echo "built $out/contact_linux64"
