// The explorer's crossing events as the audio layer's cues: passing above in w is the high ping,
// below the low thud (audio/cue_synth.hpp), for the live player and for WAV files alike.
#pragma once
#include <span>
#include <vector>

#include "audio/cue_synth.hpp"
#include "interact/live/surface_explorer.hpp"

namespace s4d {

inline CueKind explore_cue(const ExplorerEvent& e) { return e.above ? CueKind::curve_above : CueKind::curve_below; }

inline std::vector<CueEvent> explore_cues(std::span<const ExplorerEvent> events) {
  std::vector<CueEvent> out;
  out.reserve(events.size());
  for (const ExplorerEvent& e : events) out.push_back({e.time, explore_cue(e), 1.0f});
  return out;
}

}  // namespace s4d
