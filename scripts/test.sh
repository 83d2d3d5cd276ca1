#!/usr/bin/env bash
# Installs what the tests need, builds everything (release, with tests) and runs the whole suite;
# then the checked builds: the suite under ASan + UBSan, the threaded tests under TSan, and each
# libFuzzer target for a short time (CMakePresets.json, scripts/fuzz.sh). S4D_CHECKED=0 stops after
# the release suite. Prints the time of each phase at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
times=()
phase() {  # phase NAME COMMAND...: runs it and keeps its wall time for the summary
  local name=$1 start=$SECONDS
  shift
  echo "== test.sh: $name"
  "$@"
  times+=("$(printf '%-26s %4d s' "$name" $((SECONDS - start)))")
}
summary() {
  echo "== test.sh: time per phase"
  printf '  %s\n' "${times[@]}"
}
trap summary EXIT

phase "install deps" scripts/install-deps.sh test
phase "release: configure" cmake --preset release
phase "release: build" cmake --build --preset release -j"$jobs"
phase "release: tests" ctest --preset release -j"$jobs"
# The web page: emscripten's build of the window and its tests in headless Chromium (S4D_WEB=0 skips).
if [[ "${S4D_WEB:-1}" != 0 ]]; then
  phase "web: build" scripts/build-web.sh build-web/site build-web
  phase "web: tests" scripts/test-web.sh build-web/site
fi
[[ "${S4D_CHECKED:-1}" == 0 ]] && exit 0

# ASan + UBSan: the whole suite but the window (the asan preset builds no GUI: the app's window
# runs Mesa through GLX under Xvfb, uninstrumented and half a minute even in release; the app's
# logic below the window is in the interact and render tests, which run). Nor the package tests
# (label package: an instrumented program without its window is not what is packaged; the release
# suite makes and runs the .deb).
# The preset also leaves out six brute-force tests that take 75-135 s each instrumented (1-3 s in
# release): ClosestPoints.RandomAndDegenerateConfigurationsInR2/3/4, the spun trefoil's
# self-intersection check at its two finest resolutions, TrefoilRibbon.TooWideAWidth... and
# World.AdversarialRun...; the same code runs in their smaller siblings, which stay in. And two
# more: RibbonSketch.ThreadedAboveThenBelow... asserts it ends within 20 s of wall time (24 s
# instrumented); World.UndampedSymplecticRunConservesEnergy fails in the clang build (the fine
# run's energy error 0.036 against the coarse one's 0.034, where release gcc has it under a
# quarter) with no sanitizer report: a numerical difference between the compilers, open in the
# issue's note until it is understood. And, to keep the whole run within 30 minutes on 2 cores,
# the four slowest instrumented tests (1020 s of the phase's 1800 s, measured 2026-12-04):
# KnotTable.TableKnotsAreNamedBack... (every Rolfsen knot built and named, 588 s; its code runs in
# KnotTable.LinksOfTheTable and the knot tests), Relax.ScrambledUnknots... (161 s; the relax runs
# in Relax.TrefoilStaysATrefoil...), MeshProximity.CoherentQueriesEqualFreshOnesAlongAMotion (156
# s; the coherent grid run and the brute-force comparisons stay) and HapticScenes.OnItsOwnThreadA
# SlowPhysicsNeverStallsTheLoop (a timing assertion no instrumented build keeps, as under TSan).
# And the knot exercises' whole-table tests, SameKnotExercise.EveryPairIsDecidedAsTheTablesSay (804 s
# instrumented, 9 s in release: twelve pairs of relaxed table knots; it alone had made the phase
# wait 13 minutes, measured 2026-12-05) and UnknottingExercise.EveryKnotHasACrossingThatUnknotsIt
# InItsPicture (104 s, 2 s in release): cli.knot_exercise_same and cli.knot_exercise_unknot run the
# same code instrumented end to end, and the sibling exercise tests stay in. And the own knot
# engine's three whole-table comparisons with Regina (OwnEngine.PolynomialsEqualReginas..., Names
# EveryTableKnotAndLink..., NamesRelaxedAndRedrawnCurves...: 16, 38 and 68 s in release): the
# engine's code runs instrumented in their siblings (the index's HOMFLY-PT, the link table, Jones
# against the bracket state sum, signatures, codes).
phase "asan: configure" cmake --preset asan
phase "asan: build" cmake --build --preset asan -j"$jobs"
phase "asan: tests" ctest --preset asan -j"$jobs"
# TSan: the haptics, interact and audio tests (the haptic loop, the SPSC queue and triple buffer,
# the recorder, the live simulation's snapshot handover, sessions and autosave, the audio thread).
# The preset leaves out one timing test, HapticScenes.OnItsOwnThreadASlowPhysicsNeverStallsTheLoop:
# it asserts ticks of under 500 us, which no instrumented build keeps; its thread runs under TSan
# in the other OnItsOwnThread tests.
phase "tsan: configure" cmake --preset tsan
phase "tsan: build" cmake --build --preset tsan -j"$jobs"
phase "tsan: tests" ctest --preset tsan -j"$jobs"
phase "fuzz: 9 targets x 20 s, 2 at once" scripts/fuzz.sh build-asan 20
