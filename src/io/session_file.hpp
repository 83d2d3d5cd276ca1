// Session files (.s4d): everything a user's work is — the scene with every object's current
// shape inline, the live simulation's state (positions, velocities, pins, time), the 4D frame
// and view, the tool, and the undo history with its states (so Ctrl+Z works after reopening) —
// as versioned JSON. A session written by an older version opens; a newer or damaged one is
// refused with what is wrong.
#pragma once
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace s4d {

// 1: the first; 2 adds the tool settings and the held vertices; 3 the undo history's states and
// what closed the run (an older file opens without them: its history is labels only).
inline constexpr int kSessionVersion = 3;

// A document as an undo step keeps it: the scene as it was (shapes, objects, physics, view
// settings), the pins, and the window's part — its 4D slider angles, trackball, zoom and tool
// settings (app/tool_settings.hpp).
struct DocumentState {
  Scene scene;
  std::vector<int> pinned;
  std::array<float, 6> angles{};
  Eigen::Quaterniond trackball = Eigen::Quaterniond::Identity();
  double zoom = 1;
  std::map<std::string, double> settings;
  std::size_t bytes() const;  // an estimate of the memory it holds
};

struct SimulationState {
  int dim = 0;                     // 3 or 4; 0: nothing was simulated
  std::vector<double> positions;   // nv × dim, the World's vertices in body order
  std::vector<double> velocities;  // nv × dim
  std::vector<int> pinned;         // vertices held where they are
  std::vector<int> held;           // vertices the hand held on its rubber band when saved
  double time = 0;                 // s simulated
  bool playing = false;
};

// The window's view beyond the scene's own: the six 4D slider angles over the base frame, the
// trackball, the zoom and the 4D perspective.
struct SessionView {
  std::array<float, 6> angles{};  // degrees, xy xz xw yz yw zw
  Frame<4> base_frame;
  Eigen::Quaterniond trackball = Eigen::Quaterniond::Identity();
  double zoom = 1;
  double perspective = 0;  // the 4D eye's distance along w (Frame::set_perspective); 0 orthographic
};

struct SessionFile {
  Scene scene;                     // objects inline as they are now, view, physics, scenario
  std::string opened;              // what the session began from (a scene or scenario file)
  SimulationState simulation;
  SessionView view;
  std::string tool;                // the active tool's name
  std::map<std::string, double> tool_settings;  // "group.setting" -> value (app/tool_settings.hpp)
  std::vector<std::string> history;  // labels of the undoable steps, oldest first
  int history_head = 0;            // how many of them are done (the rest were undone)
  // One state per label (version 3), shared, never changed: for a done step the document before
  // it, for an undone one the document after it. Empty in older files (nothing to undo then).
  std::vector<std::shared_ptr<const DocumentState>> history_states;
  bool clean_exit = true;          // an autosave says false until the app has quit normally
  std::string closed_by;           // the signal that ended the run ("SIGTERM"), when one did
  double saved_at = 0;             // s since 1970 (wall clock) when it was written
};

// The text of history states already written, by state: a state never changes once recorded, so
// an autosave formats only the steps recorded since the last one (formatting numbers is most of
// a write: 0.2 s for 1 MB of states on a loaded laptop core). One per writer; not thread-safe.
class StateTextCache {
 public:
  const std::string& text(const std::shared_ptr<const DocumentState>& state);
  // Forgets the states no longer in `live` (the history's own bounds then bound the cache).
  void keep_only(const std::vector<std::shared_ptr<const DocumentState>>& live);
  std::size_t size() const { return texts_.size(); }

 private:
  struct Entry {
    std::weak_ptr<const DocumentState> state;  // which state the text is of (an address can be reused)
    std::string text;
  };
  std::map<const DocumentState*, Entry> texts_;
};

std::string session_text(const SessionFile& session, StateTextCache* cache = nullptr);
// Throws ParseError("file: where: what") on anything malformed; a session of a newer version is
// refused by name ("written by a newer shadow4d (version 3); this one reads 1").
SessionFile parse_session(const std::string& text, const std::filesystem::path& origin);
SessionFile read_session(const std::filesystem::path& path);

// What a start needs to know of an autosave slot without building its whole document (a long
// history is megabytes of states): its version, whether its run quit normally, when it was saved.
struct SessionSummary {
  int version = 0;
  bool clean_exit = true;
  double saved_at = 0;
};
// Throws ParseError for a file that is not JSON or not a session, as read_session does; the rest
// of the file is checked only when it is read.
SessionSummary parse_session_summary(const std::string& text, const std::filesystem::path& origin);
SessionSummary read_session_summary(const std::filesystem::path& path);
// Atomic (io/atomic_file.hpp); `keep` older versions are kept beside it.
void write_session(const SessionFile& session, const std::filesystem::path& path, int keep = 0,
                   StateTextCache* cache = nullptr);

}  // namespace s4d
