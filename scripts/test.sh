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
# The preset also leaves out the tests that are slow only for being long (the numbers: instrumented
# seconds, measured 2026-12-04..07, against a few seconds in release); the same code runs
# instrumented in their smaller siblings, which stay in:
# - brute-force sweeps: ClosestPoints.RandomAndDegenerateConfigurationsInR2/3/4 (75-135 each), the
#   spun trefoil's self-intersection check at its two finest resolutions, TrefoilRibbon.TooWide...,
#   World.AdversarialRun..., MeshProximity.CoherentQueriesEqualFresh... (156), ContactCache.ADragged
#   UpperLayer... (a drag checked against brute force every tenth step; the cache's other
#   brute-force test stays);
# - whole-table knot runs: KnotTable.TableKnotsAreNamedBack... (588), SameKnotExercise.EveryPair...
#   (804), UnknottingExercise.EveryKnot... (104), KnotNaming.IdentifyInfoAndTheTableDiagram... and
#   TheConwayAndKinoshita..., the own engine's three comparisons with Regina, KnotInfo.Twelve... (85)
#   and Thirteen... (27), SameKnot.DifferentKnots... (43), KnotNaming.TenOneThirtyTwo... (27);
# - long runs: Relax.ScrambledUnknots... (161), LiveSimulation.RelaxUntanglesTheUnknot... (149),
#   scenario.ribbon-stays-knotted-3d (46), cli.demo (55; the render tests stay), and
#   cli.session_survives_sigkill (81: fifty SIGKILLs, which no sanitizer can report on);
# - timing: RibbonSketch.ThreadedAboveThenBelow... (a 20 s deadline) and HapticScenes.OnItsOwnThread
#   ASlowPhysics... (500 us ticks);
# - World.UndampedSymplecticRunConservesEnergy: clang's build has the fine run's energy error 0.036
#   against the coarse one's 0.034 (release gcc: under a quarter), no sanitizer report; open until
#   it is understood.
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
