#!/usr/bin/env bash
# Issue 86: the IPC-2581 and ODB++ fixtures, and the Excellon drill files
# they are checked against, made from KiCad's demo boards by Debian's KiCad
# 9 (bookworm-backports, which scripts/test unpacks into build-deps/kicad9):
#   tests/data/boards/make_boards.sh
# Each board gets KiCad's own Excellon export, plated and non-plated apart
# (BOARD-PTH.drl, BOARD-NPTH.drl; mm, absolute origin), its IPC-2581 (rev C,
# mm) and its ODB++ (6 decimals: KiCad's default of 2 rounds positions to
# 10 µm). The demos are KiCad 6's (Debian 12's kicad-demos); KiCad 9 reads them.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
kicad="$root/build-deps/kicad9/usr"
export LD_LIBRARY_PATH="$kicad/lib/x86_64-linux-gnu"
demos=/usr/share/kicad/demos
cli() { "$kicad/bin/kicad-cli" "$@" 2>&1 | grep -v "schema file" || true; }

# board, the IPC-2581 form (xml | zip), the ODB++ form (tgz | zip)
make_board() {
  local pcb="$1" ipc="$2" odb="$3"
  local name work
  name="$(basename "$pcb" .kicad_pcb)"
  work="$(mktemp -d)"
  cp "$demos/$pcb" "$work/$name.kicad_pcb"
  mkdir -p "$here/$name"
  rm -f "$here/$name"/*
  cli pcb export drill --excellon-separate-th -u mm -o "$work/" "$work/$name.kicad_pcb" >/dev/null
  cp "$work/$name-PTH.drl" "$work/$name-NPTH.drl" "$here/$name/"
  if [ "$ipc" = zip ]; then
    cli pcb export ipc2581 --compress -o "$work/$name.ipc2581.zip" "$work/$name.kicad_pcb" >/dev/null
    cp "$work/$name.ipc2581.zip" "$here/$name/"
  else
    cli pcb export ipc2581 -o "$work/$name.ipc2581.xml" "$work/$name.kicad_pcb" >/dev/null
    cp "$work/$name.ipc2581.xml" "$here/$name/"
  fi
  cli pcb export odb --precision 6 --compression "$odb" -o "$work/$name.odb.$odb" "$work/$name.kicad_pcb" >/dev/null
  cp "$work/$name.odb.$odb" "$here/$name/"
  rm -rf "$work"
}

make_board pic_programmer/pic_programmer.kicad_pcb zip zip
make_board ecc83/ecc83-pp_v2.kicad_pcb xml tgz
make_board kit-dev-coldfire-xilinx_5213/kit-dev-coldfire-xilinx_5213.kicad_pcb zip tgz
ls -l "$here"/*/
