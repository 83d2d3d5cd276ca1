#!/usr/bin/env bash
# The .deb runs without the source tree: scripts/package-deb.sh makes it, it is unpacked into a
# fresh folder, and from another folder, with an environment holding no path of the source or the
# build, shadow4d names the trefoil, renders the demo and runs an installed scenario. Where a
# user mount namespace can be had (unshare), the source and build folders are covered by empty
# ones for these runs, so nothing of them is within reach; elsewhere the test says so, and
# still checks that the unpacked program holds neither path and reads its data beside itself.
#   tests/packaging/deb_runs_without_source.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$(realpath "$1")
build=$(realpath "$2")
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
inside() { [[ "$1/" == "$2/"* ]]; }  # inside A B: folder A is B or below it

# A scratch folder outside both trees (ctest's TMPDIR is inside the build).
base=
for b in /tmp /var/tmp "${HOME:-/nonexistent}"; do
  b=$(realpath -m "$b")
  if [[ -d "$b" && -w "$b" ]] && ! inside "$b" "$src" && ! inside "$b" "$build"; then
    base=$b
    break
  fi
done
[[ -n "$base" ]] || fail "no writable scratch folder outside $src and $build"
tmp=$(mktemp -d "$base/shadow4d-deb-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

"$src/scripts/package-deb.sh" "$tmp/deb" "$build" >"$tmp/package.log" 2>&1 || {
  cat "$tmp/package.log"
  fail "scripts/package-deb.sh"
}
debs=("$tmp"/deb/shadow4d_*.deb)
deb=${debs[0]}
[[ -f "$deb" ]] || fail "no .deb made"
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"
dpkg-deb -f "$deb" Package Depends
mkdir "$tmp/root" "$tmp/elsewhere" "$tmp/home"
dpkg-deb -x "$deb" "$tmp/root"
bin=$tmp/root/usr/bin/shadow4d
share=$tmp/root/usr/share

# What the package holds besides the program.
for f in shadow4d/knots/knot_index.tsv shadow4d/knots/link_table.tsv shadow4d/knots/rolfsen_braids.txt \
         shadow4d/scenarios/spun-trefoil-tighten.json shadow4d/scenes/trefoil-knot.json \
         applications/shadow4d.desktop icons/hicolor/scalable/apps/shadow4d.svg \
         icons/hicolor/256x256/apps/shadow4d.png mime/packages/shadow4d.xml man/man1/shadow4d.1.gz; do
  [[ -s "$share/$f" ]] || fail "the package has no /usr/share/$f"
done
grep -q '^MimeType=application/x-shadow4d-session;' "$share/applications/shadow4d.desktop" || fail ".desktop names no .s4d type"
gzip -t "$share/man/man1/shadow4d.1.gz" || fail "the manual page is no gzip file"
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate "$share/applications/shadow4d.desktop" || fail "desktop-file-validate"
fi
if command -v update-mime-database >/dev/null; then  # the MIME type as the desktop will read it
  cp -r "$share/mime" "$tmp/mime"
  update-mime-database "$tmp/mime" >"$tmp/mime.log" 2>&1 || { cat "$tmp/mime.log"; fail "update-mime-database"; }
  grep -q '^50:application/x-shadow4d-session:\*\.s4d$' "$tmp/mime/globs2" || fail "*.s4d is not application/x-shadow4d-session"
  echo "mime: *.s4d is application/x-shadow4d-session"
fi

# Nothing points back at the trees: no build-tree marker beside the program, neither path in it.
[[ ! -e "$tmp/root/usr/bin/shadow4d-source-data" ]] || fail "the build-tree marker was packaged"
for p in "$src" "$build"; do
  if grep -qF -- "$p" "$bin"; then fail "the program holds the path $p"; fi
done

# The runs: from another folder, with only PATH and HOME set; under unshare with the source and
# build folders covered by empty ones.
runner=("$tmp/run.sh")
cat >"$tmp/run.sh" <<'EOS'
#!/bin/sh
# run.sh SRC BUILD HIDE COMMAND...: covers SRC and BUILD (HIDE=1), then runs COMMAND.
src=$1 build=$2 hide=$3
shift 3
if [ "$hide" = 1 ]; then
  case "$build/" in "$src/"*) ;; *) mount -t tmpfs none "$build" || exit 90 ;; esac
  mount -t tmpfs none "$src" || exit 90
  [ -z "$(ls -A "$src")" ] || exit 90
fi
exec "$@"
EOS
chmod +x "$tmp/run.sh"
hide=0
if unshare -rm true 2>/dev/null; then
  hide=1
  runner=(unshare -rm "$tmp/run.sh")
  echo "source and build folders: covered by empty ones for the runs (unshare)"
else
  echo "source and build folders: left in place (no user mount namespace here); the checks above stand for it"
fi
run() {
  (cd "$tmp/elsewhere" && env -i PATH=/usr/bin:/bin HOME="$tmp/home" "${runner[@]}" "$src" "$build" "$hide" "$bin" "$@")
}
if [[ $hide == 1 ]]; then  # the cover works: the build's own program, copied out, finds no data
  mkdir "$tmp/build-copy"
  cp "$build/apps/shadow4d/shadow4d" "$build/apps/shadow4d/shadow4d-source-data" "$tmp/build-copy/"
  covered=$(bin=$tmp/build-copy/shadow4d run --version) || fail "the build's program --version"
  grep -q '^data: not found: ' <<<"$covered" || fail "the source tree is still within reach: $covered"
fi

version=$(run --version) || fail "shadow4d --version"
echo "$version"
grep -qxF "data: $share/shadow4d (installed beside $bin)" <<<"$version" || fail "the data is not read beside the program"

knot=$(run knot identify torus-knot:p=2,q=3) || fail "knot identify"
grep -q '^knot: 3_1 ' <<<"$knot" || fail "the trefoil is not named 3_1: $knot"
echo "knot identify torus-knot:p=2,q=3: $(head -1 <<<"$knot")"

demo=$(run demo --out demo --size 320x240) || { echo "$demo"; fail "demo"; }
grep -q 'demo: 8 of 8 pictures and 2 of 2 experiments (PASS)' <<<"$demo" || { echo "$demo"; fail "demo's closing line"; }
pngs=$(find "$tmp/elsewhere/demo" -name '*.png' -size +1k | wc -l)
[[ $pngs == 10 ]] || fail "demo wrote $pngs PNG files, not 10"
echo "demo: $pngs PNG files; $(tail -1 <<<"$demo")"

scenario=$share/shadow4d/scenarios/spun-trefoil-tighten.json
ran=$(run run "$scenario" --out run --frames 2) || { echo "$ran"; fail "run $scenario"; }
grep -q '^PASS spun-trefoil-tighten: ' <<<"$ran" || fail "the installed scenario did not PASS: $ran"
[[ -f "$tmp/elsewhere/run/metrics.json" ]] || fail "run wrote no metrics.json"
byname=$(run run spun-trefoil-loosen --out run2 --frames 2 --no-png) || { echo "$byname"; fail "run by name"; }
grep -q '^PASS spun-trefoil-loosen: ' <<<"$byname" || fail "run by name did not PASS: $byname"
echo "run: $(grep '^PASS' <<<"$ran" | cut -c1-60)...; by name: $(grep '^PASS' <<<"$byname" | cut -c1-40)..."
# cmake --install under another prefix: the same layout, the data found beside bin/ there too.
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
installed=$(bin=$tmp/prefix/bin/shadow4d run --version) || fail "the installed shadow4d --version"
grep -qxF "data: $tmp/prefix/share/shadow4d (installed beside $tmp/prefix/bin/shadow4d)" <<<"$installed" ||
  fail "cmake --install: the data is not read beside the program: $installed"
knot=$(bin=$tmp/prefix/bin/shadow4d run knot identify torus-knot:p=2,q=3) || fail "the installed knot identify"
grep -q '^knot: 3_1 ' <<<"$knot" || fail "cmake --install: the trefoil is not named 3_1"
echo "cmake --install --prefix: data beside bin/, the trefoil named 3_1"
echo "package: PASS"
