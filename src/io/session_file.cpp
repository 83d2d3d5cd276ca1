// The session's JSON: {"shadow4d_session": version, "clean_exit", "closed_by", "saved_at",
// "scene": {...}, "simulation": {...}, "view": {...}, "tool", "tool_settings": {...},
// "history": [...], "history_head", "history_states": [...]}.
#include "io/session_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

using Json = nlohmann::ordered_json;

struct Ctx {
  std::string file;
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw ParseError(file, 0, where + ": " + what);
  }
  double number(const Json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(where, "must be finite");
    return v;
  }
  std::vector<double> numbers(const Json& j, const std::string& where) const {
    if (!j.is_array()) fail(where, "must be an array of numbers");
    std::vector<double> v;
    v.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) v.push_back(number(j[i], where + "[" + std::to_string(i) + "]"));
    return v;
  }
};

Json quaternion_json(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

Eigen::Quaterniond parse_quaternion(const Ctx& c, const Json& j, const std::string& where) {
  const auto t = c.numbers(j, where);
  if (t.size() != 4 || !(std::hypot(std::hypot(t[0], t[1]), std::hypot(t[2], t[3])) > 1e-9))
    c.fail(where, "must be a non-zero quaternion [w, x, y, z]");
  return Eigen::Quaterniond(t[0], t[1], t[2], t[3]).normalized();
}

std::array<float, 6> parse_angles(const Ctx& c, const Json& j, const std::string& where) {
  const auto a = c.numbers(j, where);
  if (a.size() != 6) c.fail(where, "must be 6 angles (xy xz xw yz yw zw)");
  std::array<float, 6> out{};
  for (std::size_t i = 0; i < 6; ++i) out[i] = static_cast<float>(a[i]);
  return out;
}

std::map<std::string, double> parse_settings(const Ctx& c, const Json& j, const std::string& where) {
  if (!j.is_object()) c.fail(where, "must be an object of named numbers");
  std::map<std::string, double> out;
  for (const auto& [k, v] : j.items()) out[k] = c.number(v, where + "." + k);
  return out;
}

Json settings_json(const std::map<std::string, double>& settings) {
  Json j = Json::object();
  for (const auto& [k, v] : settings)
    if (std::isfinite(v)) j[k] = v;
  return j;
}

// One undo step's document: its scene inline, as the session's own.
Json state_json(const DocumentState& d) {
  return {{"scene", Json::parse(scene_text(d.scene, "session.s4d", ObjectStorage::kInline))},
          {"pinned", d.pinned},
          {"angles", d.angles},
          {"trackball", quaternion_json(d.trackball)},
          {"zoom", d.zoom},
          {"settings", settings_json(d.settings)}};
}

std::shared_ptr<const DocumentState> parse_state(const Ctx& c, const Json& j, const std::string& where,
                                                 const std::filesystem::path& origin) {
  if (!j.is_object()) c.fail(where, "must be an object");
  for (const auto& [k, v] : j.items())
    if (k != "scene" && k != "pinned" && k != "angles" && k != "trackball" && k != "zoom" && k != "settings")
      c.fail(where + "." + k, "unknown key");
  auto d = std::make_shared<DocumentState>();
  if (!j.contains("scene") || !j["scene"].is_object()) c.fail(where + ".scene", "missing");
  try {
    d->scene = parse_scene(j["scene"].dump(), origin);
  } catch (const ParseError& e) {  // said again with which step's scene it is
    std::string what = e.what();
    if (what.rfind(c.file + ":", 0) == 0) what.erase(0, c.file.size() + 1);
    while (!what.empty() && what.front() == ' ') what.erase(0, 1);
    c.fail(where + ".scene", what);
  }
  for (double v : c.numbers(j.value("pinned", Json::array()), where + ".pinned")) {
    if (v < 0 || v > 1e9 || v != std::floor(v)) c.fail(where + ".pinned", "vertex " + format_double(v) + " is no vertex");
    d->pinned.push_back(static_cast<int>(v));
  }
  d->angles = parse_angles(c, j.value("angles", Json::array({0, 0, 0, 0, 0, 0})), where + ".angles");
  d->trackball = parse_quaternion(c, j.value("trackball", Json::array({1, 0, 0, 0})), where + ".trackball");
  d->zoom = c.number(j.value("zoom", Json(1)), where + ".zoom");
  if (!(d->zoom > 0)) c.fail(where + ".zoom", "must be positive");
  if (j.contains("settings")) d->settings = parse_settings(c, j["settings"], where + ".settings");
  return d;
}

}  // namespace

std::size_t DocumentState::bytes() const {
  std::size_t b = sizeof(DocumentState) + pinned.size() * sizeof(int) + scene.scenario.size();
  for (const SceneObject& o : scene.objects) {
    b += sizeof(SceneObject) + o.name.size();
    std::visit([&](const auto& s) {
      using T = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
        b += s.vertices.size() * sizeof(s.vertices[0]) + s.triangles.size() * sizeof(Triangle);
      } else {
        for (const auto& c : s.components) b += c.points.size() * sizeof(c.points[0]) + sizeof(c);
      }
    }, o.shape);
  }
  return b;
}

const std::string& StateTextCache::text(const std::shared_ptr<const DocumentState>& state) {
  Entry& e = texts_[state.get()];
  const bool same = !e.state.owner_before(state) && !state.owner_before(e.state) && !e.state.expired();
  if (!same || e.text.empty()) {
    e.state = state;
    e.text = state_json(*state).dump();
  }
  return e.text;
}

void StateTextCache::keep_only(const std::vector<std::shared_ptr<const DocumentState>>& live) {
  std::map<const DocumentState*, Entry> kept;
  for (const auto& s : live)
    if (auto it = texts_.find(s.get()); it != texts_.end()) kept.insert(texts_.extract(it));
  texts_ = std::move(kept);
}

std::string session_text(const SessionFile& s, StateTextCache* cache) {
  Json root;
  root["shadow4d_session"] = kSessionVersion;
  // First, so that a start learns how the run ended from the file's opening bytes
  // (read_session_summary) however long its history.
  root["clean_exit"] = s.clean_exit;
  if (!s.closed_by.empty()) root["closed_by"] = s.closed_by;
  root["saved_at"] = s.saved_at;
  root["opened"] = s.opened;
  root["scene"] = Json::parse(scene_text(s.scene, "session.s4d", ObjectStorage::kInline));
  const SimulationState& sim = s.simulation;
  root["simulation"] = {{"dim", sim.dim},           {"positions", sim.positions}, {"velocities", sim.velocities},
                        {"pinned", sim.pinned},     {"held", sim.held},
                        {"time", sim.time},         {"playing", sim.playing}};
  Json base = Json::array();
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) base.push_back(s.view.base_frame.matrix()(r, k));
  root["view"] = {{"angles", s.view.angles}, {"base_frame", base},
                  {"trackball", quaternion_json(s.view.trackball)}, {"zoom", s.view.zoom}};
  if (s.view.perspective > 0) root["view"]["perspective"] = s.view.perspective;  // orthographic files stay as they were
  root["tool"] = s.tool;
  root["tool_settings"] = settings_json(s.tool_settings);
  root["history"] = s.history;
  root["history_head"] = s.history_head;
  try {
    // The states last, and without indentation: they are most of the file, and read by no person.
    std::string text = root.dump(1);
    if (!s.history_states.empty() && s.history_states.size() == s.history.size()) {
      text.pop_back();  // the closing brace
      text += ",\n \"history_states\": [";
      for (std::size_t i = 0; i < s.history_states.size(); ++i) {
        text += i == 0 ? "\n  " : ",\n  ";
        text += cache ? cache->text(s.history_states[i]) : state_json(*s.history_states[i]).dump();
      }
      text += "\n ]\n}";
    }
    if (cache) cache->keep_only(s.history_states);
    return text + "\n";
  } catch (const Json::exception& e) {  // e.g. a name that is not UTF-8
    throw Error(std::string("cannot write the session: ") + e.what());
  }
}

SessionFile parse_session(const std::string& text, const std::filesystem::path& origin) {
  const Ctx c{origin.string()};
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::exception& e) {
    throw ParseError(c.file, 0, std::string("not a session (damaged or not JSON): ") + e.what());
  }
  if (!root.is_object() || !root.contains("shadow4d_session")) c.fail("shadow4d_session", "missing: this is no session file");
  const double version = c.number(root["shadow4d_session"], "shadow4d_session");
  if (version > kSessionVersion)
    c.fail("shadow4d_session", "written by a newer shadow4d (version " + format_double(version) + "); this one reads " +
                                   std::to_string(kSessionVersion));
  if (version < 1 || version != std::floor(version)) c.fail("shadow4d_session", "not a version number");
  for (const auto& [k, v] : root.items())
    if (k != "shadow4d_session" && k != "opened" && k != "scene" && k != "simulation" && k != "view" && k != "tool" &&
        k != "tool_settings" && k != "history" && k != "history_head" && k != "history_states" && k != "clean_exit" &&
        k != "closed_by" && k != "saved_at")
      c.fail(k, "unknown key");
  SessionFile s;
  if (root.contains("opened")) {
    if (!root["opened"].is_string()) c.fail("opened", "must be a string");
    s.opened = root["opened"].get<std::string>();
  }
  if (!root.contains("scene") || !root["scene"].is_object()) c.fail("scene", "missing");
  s.scene = parse_scene(root["scene"].dump(), origin);  // errors name the file and the key
  if (root.contains("simulation")) {
    const Json& j = root["simulation"];
    if (!j.is_object()) c.fail("simulation", "must be an object");
    SimulationState& sim = s.simulation;
    const double dim = c.number(j.value("dim", Json(0)), "simulation.dim");
    if (dim != 0 && dim != 3 && dim != 4) c.fail("simulation.dim", "must be 0, 3 or 4");
    sim.dim = static_cast<int>(dim);
    sim.positions = c.numbers(j.value("positions", Json::array()), "simulation.positions");
    sim.velocities = c.numbers(j.value("velocities", Json::array()), "simulation.velocities");
    if (sim.dim > 0 && sim.positions.size() % static_cast<std::size_t>(sim.dim) != 0)
      c.fail("simulation.positions", "is not a whole number of points of R^" + std::to_string(sim.dim));
    if (!sim.velocities.empty() && sim.velocities.size() != sim.positions.size())
      c.fail("simulation.velocities", "must have as many values as the positions");
    const std::size_t nv = sim.dim > 0 ? sim.positions.size() / static_cast<std::size_t>(sim.dim) : 0;
    const auto vertices = [&](const char* key) {
      std::vector<int> out;
      const std::string where = std::string("simulation.") + key;
      for (double v : c.numbers(j.value(key, Json::array()), where)) {
        if (v < 0 || v >= static_cast<double>(nv) || v != std::floor(v))
          c.fail(where, "vertex " + format_double(v) + " is not one of the " + std::to_string(nv));
        out.push_back(static_cast<int>(v));
      }
      return out;
    };
    sim.pinned = vertices("pinned");
    sim.held = vertices("held");
    sim.time = c.number(j.value("time", Json(0)), "simulation.time");
    if (j.contains("playing")) {
      if (!j["playing"].is_boolean()) c.fail("simulation.playing", "must be true or false");
      sim.playing = j["playing"].get<bool>();
    }
  }
  if (root.contains("view")) {
    const Json& j = root["view"];
    if (!j.is_object()) c.fail("view", "must be an object");
    s.view.angles = parse_angles(c, j.value("angles", Json::array({0, 0, 0, 0, 0, 0})), "view.angles");
    s.view.base_frame = s.scene.frame;  // version 1 wrote the composed frame alone
    if (j.contains("base_frame")) {
      const auto m = c.numbers(j["base_frame"], "view.base_frame");
      if (m.size() != 16) c.fail("view.base_frame", "must be 16 numbers (a 4 x 4 rotation, row by row)");
      Mat<4> r;
      for (int i = 0; i < 16; ++i) r(i / 4, i % 4) = m[static_cast<std::size_t>(i)];
      s.view.base_frame = Frame<4>(r);
    }
    s.view.trackball = parse_quaternion(c, j.value("trackball", Json::array({1, 0, 0, 0})), "view.trackball");
    s.view.zoom = c.number(j.value("zoom", Json(1)), "view.zoom");
    if (!(s.view.zoom > 0)) c.fail("view.zoom", "must be positive");
    if (j.contains("perspective")) {
      s.view.perspective = c.number(j["perspective"], "view.perspective");
      if (s.view.perspective != 0)  // 0: orthographic
        if (const std::string e = Frame<4>::perspective_error(s.view.perspective); !e.empty()) c.fail("view.perspective", e);
    }
  }
  if (root.contains("tool")) {
    if (!root["tool"].is_string()) c.fail("tool", "must be a string");
    s.tool = root["tool"].get<std::string>();
  }
  if (root.contains("tool_settings")) s.tool_settings = parse_settings(c, root["tool_settings"], "tool_settings");
  if (root.contains("history")) {
    if (!root["history"].is_array()) c.fail("history", "must be an array of labels");
    for (const Json& h : root["history"]) {
      if (!h.is_string()) c.fail("history", "must be an array of labels");
      s.history.push_back(h.get<std::string>());
    }
  }
  // Checked as a double first: a huge value would not fit the int (undefined behaviour), and 0.5
  // is no step of the history.
  const double head = c.number(root.value("history_head", Json(static_cast<double>(s.history.size()))), "history_head");
  if (head < 0 || head > static_cast<double>(s.history.size()) || head != std::floor(head))
    c.fail("history_head", "is outside the history");
  s.history_head = static_cast<int>(head);
  if (root.contains("history_states")) {
    const Json& j = root["history_states"];
    if (!j.is_array()) c.fail("history_states", "must be an array of states");
    if (j.size() != s.history.size())
      c.fail("history_states", "must hold one state per step of the history (" + std::to_string(s.history.size()) +
                                   "), has " + std::to_string(j.size()));
    for (std::size_t i = 0; i < j.size(); ++i)
      s.history_states.push_back(parse_state(c, j[i], "history_states[" + std::to_string(i) + "]", origin));
  }
  if (root.contains("saved_at")) s.saved_at = c.number(root["saved_at"], "saved_at");
  if (root.contains("clean_exit")) {
    if (!root["clean_exit"].is_boolean()) c.fail("clean_exit", "must be true or false");
    s.clean_exit = root["clean_exit"].get<bool>();
  }
  if (root.contains("closed_by")) {
    if (!root["closed_by"].is_string()) c.fail("closed_by", "must be a string");
    s.closed_by = root["closed_by"].get<std::string>();
  }
  return s;
}

SessionFile read_session(const std::filesystem::path& path) { return parse_session(read_text_file(path), path); }

namespace {

// Reads the top level's three fields as the parser passes them and builds nothing else.
class SummarySax final : public nlohmann::json_sax<Json> {
 public:
  SessionSummary summary;
  bool has_version = false;
  bool complete = false;  // every field read: the parse stopped early
  std::string error;

  bool null() override { return value(); }
  bool boolean(bool v) override {
    if (depth_ == 1 && key_ == "clean_exit") {
      summary.clean_exit = v;
      has_clean_exit_ = true;
    }
    return value();
  }
  bool number_integer(number_integer_t v) override { return number(static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return number(static_cast<double>(v)); }
  bool number_float(number_float_t v, const string_t&) override { return number(v); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    if (depth_ == 1) key_ = k;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    return false;
  }

 private:
  bool number(double v) {
    if (depth_ == 1 && key_ == "shadow4d_session") {
      // Clamped before the cast: a huge number is a version from the future, never UB.
      summary.version = v == std::floor(v) ? static_cast<int>(std::clamp(v, -1.0, 1e9)) : -1;
      has_version = true;
    }
    if (depth_ == 1 && key_ == "saved_at" && std::isfinite(v)) {
      summary.saved_at = v;
      has_saved_at_ = true;
    }
    return value();
  }
  // Files since this reader write the three first: the parse stops there. Older ones (the three
  // last) are scanned to the end.
  bool value() {
    complete = has_version && has_clean_exit_ && has_saved_at_;
    return !complete;
  }
  bool open() {
    ++depth_;
    return true;
  }
  bool close() {
    --depth_;
    return true;
  }
  int depth_ = 0;
  std::string key_;
  bool has_clean_exit_ = false, has_saved_at_ = false;
};

}  // namespace

SessionSummary parse_session_summary(const std::string& text, const std::filesystem::path& origin) {
  const Ctx c{origin.string()};
  SummarySax sax;
  if (!Json::sax_parse(text, &sax) && !sax.complete)
    throw ParseError(c.file, 0, "not a session (damaged or not JSON): " + sax.error);
  if (!sax.has_version) c.fail("shadow4d_session", "missing: this is no session file");
  if (sax.summary.version > kSessionVersion)
    c.fail("shadow4d_session", "written by a newer shadow4d (version " + std::to_string(sax.summary.version) +
                                   "); this one reads " + std::to_string(kSessionVersion));
  if (sax.summary.version < 1) c.fail("shadow4d_session", "not a version number");
  return sax.summary;
}

SessionSummary read_session_summary(const std::filesystem::path& path) {
  // The opening bytes hold the three fields in files written since they come first; an older file
  // (or one whose opening does not hold them) is read whole.
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read " + path.string());
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  try {
    return parse_session_summary(head, path);
  } catch (const ParseError&) {
    if (in.gcount() < 4096) throw;  // that was the whole file
  }
  return parse_session_summary(read_text_file(path), path);
}

void write_session(const SessionFile& session, const std::filesystem::path& path, int keep, StateTextCache* cache) {
  write_file_atomically(path, session_text(session, cache), keep);
}

}  // namespace s4d
