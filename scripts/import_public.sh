#!/bin/sh
# Import every CONTACT deck of reference/contact_public/ into scenes/contact_public/ (issue 32
# item 4): `creepbench import contact --supported-only`, one scene per supported history; the
# cases that are not supported are listed by the importer and by the report's section
# "CONTACT's public examples". Run from the repository root after `cargo build --release`.
set -eu
bin=${CREEPBENCH:-./target/release/creepbench}
out=scenes/contact_public
mkdir -p "$out"
find reference/contact_public -name '*.inp' | LC_ALL=C sort | while read -r deck; do
    # A deck with no supported case is refused (exit 2, the reasons above); the next deck goes on.
    "$bin" import contact "$deck" --out "$out" --supported-only --overwrite || echo "$deck: no scene written"
done
