#!/usr/bin/env bash
# Issue 54: acodrill.exe (scripts/windows) under Wine behaves as acodrill does
# on Linux. It plans a DXF, KiCad's Excellon and Gerber X2 drill files (one
# with CRLF line ends, one under a path with spaces, given with backslashes)
# to LinuxCNC programs that the Linux acodrill's verify accepts and LinuxCNC's
# rs274 reads back to every hole; a bad input is exit 2, one error line and no
# file, an existing program is replaced whole; and says whether the program
# is byte-identical to Linux's, on one thread as on two.
#   tests/windows/wine_test.sh BUILD_WINDOWS_DIR LINUX_BUILD_DIR
set -uo pipefail
win="$1"; linux="$2"
root=$(cd "$(dirname "$0")/../.." && pwd)
exe="$win/bin/acodrill.exe"
acodrill="$linux/bin/acodrill"
export WINEDEBUG=-all
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0; failed=0
ok() { passed=$((passed + 1)); echo "ok: $*"; }
bad() { failed=$((failed + 1)); echo "FAILED: $*"; }
# A path as Windows sees the Linux file system (Wine's Z: drive), with backslashes.
winpath() { echo "Z:$1" | tr '/' '\\'; }

# rs274's holes: downward feeds at one XY (one per hole), in a folder of its own that is its HOME too
# (LinuxCNC 2.9 maps its tool data into $HOME/.tool.mmap, shared by every rs274 of the user: issue 85).
rs274_holes() {
  local d; d=$(mktemp -d)
  sed 's/G53 G00 Z0\./G00 Z100./' "$1" > "$d/p.ngc"
  grep -o 'T[0-9]*' "$1" | sort -u | sed 's/T\([0-9]*\)/T\1 P\1 Z0 D1/' > "$d/tool.tbl"
  (cd "$d" && HOME="$d" rs274 -t tool.tbl -g p.ngc 2>/dev/null) | awk '
    /STRAIGHT_TRAVERSE|STRAIGHT_FEED/ {
      s = $0; sub(/.*\(/, "", s); sub(/\).*/, "", s); split(s, v, ", ")
      if (v[1] != x || v[2] != y) { fresh = 1 }
      else if ($0 ~ /STRAIGHT_FEED/ && v[3] < z) { if (fresh) n++; fresh = 0 }
      if ($0 ~ /STRAIGHT_TRAVERSE/ && v[3] > z) fresh = 1
      x = v[1]; y = v[2]; z = v[3] }
    END { print n + 0 }'
  rm -rf "$d"
}

mkdir -p "$work/a folder with spaces"
cp "$root/tests/data/kicad/video-mm-decimal.drl" "$work/a folder with spaces/video.drl"
sed 's/$/\r/' "$root/tests/data/kicad/pic_programmer-inch-decimal.drl" > "$work/pic-crlf.drl"
gerber=$(ls "$root"/tests/data/real-gerber/kicad/flat_hierarchy/x2_mm46/flat_hierarchy-PTH-drl.gbr)
cases=(
  "$root/samples/plate70.dxf|dxf"
  "$work/a folder with spaces/video.drl|excellon, a path with spaces"
  "$work/pic-crlf.drl|excellon, CRLF"
  "$gerber|gerber x2"
)
for c in "${cases[@]}"; do
  input="${c%%|*}"; what="${c#*|}"
  out="$work/out.ngc"; rm -f "$out"
  opts=(--dialect linuxcnc --iterations 40 --seed 3 --threads 2 --slots skip -q)
  if ! wine "$exe" plan "$(winpath "$input")" -o "$(winpath "$out")" "${opts[@]}" 2>"$work/err"; then
    bad "$what: acodrill.exe plan failed: $(cat "$work/err")"; continue
  fi
  if "$acodrill" verify "$out" --holes "$input" --slots skip -q >/dev/null; then ok "$what: verify accepts the Windows program"
  else bad "$what: verify refuses the Windows program"; fi
  expected=$("$acodrill" holes "$input" --slots skip -q | tail -n +2 | wc -l)
  got=$(rs274_holes "$out")
  if [ "$got" = "$expected" ]; then ok "$what: rs274 reads $got holes"; else bad "$what: rs274 reads $got holes, the input has $expected"; fi
  "$acodrill" plan "$input" -o "$work/linux.ngc" "${opts[@]}"
  # The same input, options and seed: the same program, byte for byte, on Windows as on Linux.
  if cmp -s "$out" "$work/linux.ngc"; then ok "$what: byte-identical to Linux's program"
  else bad "$what: not byte-identical to Linux's: $(diff "$out" "$work/linux.ngc" | head -n 4 | tr '\n' ' ')"; fi
done
# And on one thread as on two.
wine "$exe" plan "$(winpath "$root/samples/plate70.dxf")" -o "$(winpath "$work/one.ngc")" --iterations 40 --seed 3 --threads 1 -q
wine "$exe" plan "$(winpath "$root/samples/plate70.dxf")" -o "$(winpath "$work/two.ngc")" --iterations 40 --seed 3 --threads 2 -q
if cmp -s "$work/one.ngc" "$work/two.ngc"; then ok "one thread or two: the same program"; else bad "one thread and two differ"; fi

# A bad input: exit 2, one line on stderr, no file; an existing program stays as it was.
printf 'M48\nMETRIC\nT1C0.8\n%%\nT1\nX1.0Y\n' > "$work/bad.drl"
wine "$exe" plan "$(winpath "$work/bad.drl")" -o "$(winpath "$work/bad.ngc")" 2>"$work/err"; code=$?
lines=$(grep -c . "$work/err")
if [ "$code" = 2 ] && [ "$lines" = 1 ] && grep -q '^acodrill: error: .*bad.drl:6: ' "$work/err" && [ ! -e "$work/bad.ngc" ]; then
  ok "bad input: exit 2, one line, no file"
else bad "bad input: exit $code, $lines line(s): $(cat "$work/err"), file: $(ls "$work/bad.ngc" 2>&1)"; fi
echo "keep me" > "$work/kept.ngc"
wine "$exe" plan "$(winpath "$work/bad.drl")" -o "$(winpath "$work/kept.ngc")" 2>/dev/null
if [ "$(cat "$work/kept.ngc")" = "keep me" ] && [ -z "$(ls "$work" | grep '\.tmp-')" ]; then ok "an existing file is left untouched on error, no temporary left"
else bad "the existing file was touched or a temporary is left"; fi
# Written over: the temporary file replaces an existing program whole.
wine "$exe" plan "$(winpath "$root/samples/plate10.dxf")" -o "$(winpath "$work/kept.ngc")" -q --iterations 5
if tail -n 2 "$work/kept.ngc" | head -n 1 | grep -q '^M30' && [ -z "$(ls "$work" | grep '\.tmp-')" ]; then ok "an existing program is replaced by the new one"
else bad "the program was not replaced: $(head -c 100 "$work/kept.ngc")"; fi
# Issue 85: a device is written in place, never replaced: NUL and nul.txt (Windows' null device in any
# case and with any extension) plan with exit 0 and leave no file of that name nor any temporary; a
# folder given as the program is one line, exit 2.
for dev in NUL nul.txt; do
  if (cd "$work" && wine "$exe" plan "$(winpath "$root/samples/plate10.dxf")" -o "$dev" --report "$dev" -q --iterations 5 2>"$work/err") &&
     [ ! -e "$work/$dev" ] && [ -z "$(ls "$work" | grep -i '^nul\|\.tmp-')" ]; then ok "-o $dev: written to the device, no file made"
  else bad "-o $dev: $(cat "$work/err"), files: $(ls "$work" | tr '\n' ' ')"; fi
done
mkdir -p "$work/a folder"
wine "$exe" plan "$(winpath "$root/samples/plate10.dxf")" -o "$(winpath "$work/a folder")" 2>"$work/err"; code=$?
if [ "$code" = 2 ] && [ "$(grep -c . "$work/err")" = 1 ] && grep -q 'is a directory' "$work/err"; then ok "-o a folder: exit 2, one line"
else bad "-o a folder: exit $code: $(cat "$work/err")"; fi
# Usage errors and --help.
wine "$exe" plan 2>"$work/err" >/dev/null; code=$?
if [ "$code" = 2 ] && [ "$(grep -c . "$work/err")" = 1 ]; then ok "usage error: exit 2, one line"; else bad "usage error: exit $code"; fi
if wine "$exe" --help | grep -q "acodrill plan"; then ok "--help"; else bad "--help"; fi
if wine "$win/bin/acobench.exe" --instances "$(winpath "$root/tests/data/tsplib/d198.tsp")" --iterations 5 --seeds 1 --threads 1 \
     --out "$(winpath "$work/runs.csv")" >/dev/null 2>&1 && grep -q '^instance,' "$work/runs.csv"; then ok "acobench.exe runs a sweep"
else bad "acobench.exe"; fi

# Issue 68: names outside the ANSI code page, in folders named so too (Japanese, Cyrillic, Polish,
# Spanish): a DXF and an Excellon file planned with --report and --setup-sheet, the summary naming the
# program as typed, the program the same bytes as Linux's for the same name, verified by both builds
# and read back by rs274; and a missing such file named right in the error line.
unicode_cases=("基板|ボード|出力" "Платы|плата|программа" "Płytki Łukasza|płytka_żółw|wyjście" "Placas de José|tarjeta_ñandú|programa_ñ")
for c in "${unicode_cases[@]}"; do
  IFS='|' read -r folder stem outstem <<<"$c"
  dir="$work/$folder"; mkdir -p "$dir"
  cp "$root/samples/plate10.dxf" "$dir/$stem.dxf"
  cp "$root/tests/data/kicad/video-mm-decimal.drl" "$dir/$stem.drl"
  for input in "$dir/$stem.dxf" "$dir/$stem.drl"; do
    what="$folder/$(basename "$input")"
    out="$dir/$outstem.ngc"; rm -f "$out" "$dir/$outstem.json" "$dir/$outstem.html"
    opts=(--dialect linuxcnc --iterations 20 --seed 3 --slots skip)
    if ! wine "$exe" plan "$(winpath "$input")" -o "$(winpath "$out")" --report "$(winpath "$dir/$outstem.json")" \
         --setup-sheet "$(winpath "$dir/$outstem.html")" "${opts[@]}" 2>"$work/err"; then
      bad "$what: acodrill.exe plan failed: $(cat "$work/err")"; continue
    fi
    if [ -s "$out" ] && [ -s "$dir/$outstem.json" ] && [ -s "$dir/$outstem.html" ]; then ok "$what: program, report and setup sheet written"
    else bad "$what: an output is missing: $(ls "$dir")"; fi
    if grep -qF "program: $(winpath "$out")" "$work/err"; then ok "$what: the summary names $outstem.ngc as typed"
    else bad "$what: the summary garbles the name: $(grep 'program:' "$work/err")"; fi
    if "$acodrill" verify "$out" --holes "$input" --slots skip -q >/dev/null && \
       wine "$exe" verify "$(winpath "$out")" --holes "$(winpath "$input")" --slots skip -q >/dev/null 2>&1; then
      ok "$what: verify (Linux and Windows) accepts the program"
    else bad "$what: verify refuses the program"; fi
    expected=$("$acodrill" holes "$input" --slots skip -q | tail -n +2 | wc -l)
    got=$(rs274_holes "$out")
    if [ "$got" = "$expected" ]; then ok "$what: rs274 reads $got holes"; else bad "$what: rs274 reads $got holes of $expected"; fi
    "$acodrill" plan "$input" -o "$dir/linux.ngc" "${opts[@]}" -q
    if cmp -s "$out" "$dir/linux.ngc"; then ok "$what: the same bytes as Linux's program"
    else bad "$what: not the same bytes as Linux's: $(diff "$out" "$dir/linux.ngc" | head -n 4 | tr '\n' ' ')"; fi
  done
  # KiCad's two drill files of one board, as the plugin hands them over: one job.
  cp "$root/tests/data/kicad/video-mm-decimal.drl" "$dir/$stem-PTH.drl"
  if wine "$exe" plan "$(winpath "$dir/$stem-PTH.drl")" "$(winpath "$dir/$stem.drl")" -o "$(winpath "$dir/$outstem-kicad.ngc")" \
       --machine router --dialect grbl --iterations 10 -q 2>"$work/err" && [ -s "$dir/$outstem-kicad.ngc" ]; then
    ok "$folder: the plugin's command (two drill files) plans"
  else bad "$folder: the plugin's command failed: $(cat "$work/err")"; fi
  wine "$exe" plan "$(winpath "$dir/нет_$stem.drl")" -o "$(winpath "$dir/x.ngc")" 2>"$work/err"; code=$?
  if [ "$code" = 2 ] && grep -qF "нет_$stem.drl: cannot read" "$work/err"; then ok "$folder: a missing file is named right"
  else bad "$folder: missing file: exit $code: $(cat "$work/err")"; fi
done

echo "wine: $passed passed, $failed failed"
[ "$failed" = 0 ]
