// Text format of device trajectories and the background recording writer.
//
//   # shadow4d haptic trajectory v1
//   rate 1000
//   device sim
//   scene sticky-plane
//   caps <max_force> <max_continuous> <max_stiffness> <max_rate> <outputs_force 0|1> <min xyz> <max xyz>
//   param H 500            (a name may have spaces: param max force 2)
//   setup <free text up to the end of the line: how the scene was built>
//   tick <tick> <events> <buttons> <x y z> <vx vy vz> <tx ty tz> <fx fy fz>
#include "haptics/trajectory_file.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/chars.hpp"
#include "core/error.hpp"

namespace s4d {
namespace {

constexpr const char* kMagic = "# shadow4d haptic trajectory v1";

void append_number(std::string& out, double v) {
  char buf[32];
  const auto r = double_to_chars(buf, buf + sizeof buf, v);  // shortest exact round-trip
  out.push_back(' ');
  out.append(buf, r.ptr);
}

template <typename T>
void append_int(std::string& out, T v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.push_back(' ');
  out.append(buf, r.ptr);
}

// Splits a line into whitespace-separated words.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> w;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) w.push_back(line.substr(start, i - start));
  }
  return w;
}

struct LineReader {
  std::string file;
  int line = 0;

  [[noreturn]] void fail(const std::string& msg) const { throw ParseError(file, line, msg); }

  double number(std::string_view w) const {
    double v = 0;
    const auto r = double_from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size()) fail("not a number: '" + std::string(w) + "'");
    if (!std::isfinite(v)) fail("non-finite value: '" + std::string(w) + "'");
    return v;
  }
  template <typename T>
  T integer(std::string_view w) const {
    T v = 0;
    const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size())
      fail("not a non-negative integer: '" + std::string(w) + "'");
    return v;
  }
  void expect(const std::vector<std::string_view>& w, std::size_t n, const char* what) const {
    if (w.size() != n)
      fail(std::string(what) + " needs " + std::to_string(n - 1) + " values, found " +
           std::to_string(w.size() - 1));
  }
};

}  // namespace

DeviceState TickRecord::state() const {
  DeviceState s;
  s.position = Vec3(position[0], position[1], position[2]);
  s.velocity = Vec3(velocity[0], velocity[1], velocity[2]);
  s.target = Vec3(target[0], target[1], target[2]);
  s.buttons = buttons;
  return s;
}

void TickRecord::set_state(const DeviceState& s) {
  for (int i = 0; i < 3; ++i) {
    position[i] = s.position[i];
    velocity[i] = s.velocity[i];
    target[i] = s.target[i];
  }
  buttons = s.buttons;
}

// A name as the one word the header's line holds: "OpenHaptics Phantom Omni" reads back as
// OpenHaptics_Phantom_Omni instead of making the whole file unreadable.
std::string one_word(const std::string& name) {
  std::string w = name;
  for (char& c : w)
    if (static_cast<unsigned char>(c) <= ' ') c = '_';
  return w.empty() ? "unnamed" : w;
}

std::string format_header(const TrajectoryHeader& h) {
  std::string out = std::string(kMagic) + "\nrate";
  append_number(out, h.rate);
  out += "\ndevice " + one_word(h.device) + "\nscene " + one_word(h.scene) + "\ncaps";
  const DeviceCapabilities& c = h.caps;
  for (double v : {c.max_force, c.max_continuous_force, c.max_stiffness, c.max_force_rate})
    append_number(out, v);
  out += c.outputs_force ? " 1" : " 0";
  for (int i = 0; i < 3; ++i) append_number(out, c.workspace_min[i]);
  for (int i = 0; i < 3; ++i) append_number(out, c.workspace_max[i]);
  out += '\n';
  if (!h.setup.empty()) out += "setup " + h.setup + "\n";
  for (const auto& [name, value] : h.params) {
    out += "param " + name;
    append_number(out, value);
    out += '\n';
  }
  return out;
}

void append_record(std::string& out, const TickRecord& r) {
  out += "tick";
  append_int(out, r.tick);
  append_int(out, r.events);
  append_int(out, r.buttons);
  for (const double* a : {r.position, r.velocity, r.target, r.force})
    for (int i = 0; i < 3; ++i) append_number(out, a[i]);
  out += '\n';
}

Trajectory read_trajectory(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open trajectory file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error("cannot read trajectory file '" + path.string() + "'");
  return parse_trajectory(std::move(text).str(), path.string());
}

Trajectory parse_trajectory(std::string_view text, const std::string& origin) {
  Trajectory t;
  LineReader lr{origin};
  bool magic = false;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    ++lr.line;
    if (lr.line == 1) {
      if (line.rfind(kMagic, 0) != 0) lr.fail("not a shadow4d haptic trajectory (first line must be '" +
                                              std::string(kMagic) + "')");
      magic = true;
      continue;
    }
    const auto w = words(line);
    if (w.empty() || w[0].front() == '#') continue;
    if (w[0] == "tick") {
      lr.expect(w, 16, "tick");
      TickRecord r;
      r.tick = lr.integer<std::uint64_t>(w[1]);
      r.events = lr.integer<std::uint32_t>(w[2]);
      r.buttons = lr.integer<std::uint32_t>(w[3]);
      double* arrays[] = {r.position, r.velocity, r.target, r.force};
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) arrays[a][i] = lr.number(w[4 + 3 * a + i]);
      if (!t.ticks.empty() && r.tick <= t.ticks.back().tick) lr.fail("tick numbers must increase");
      t.ticks.push_back(r);
    } else if (w[0] == "rate") {
      lr.expect(w, 2, "rate");
      t.header.rate = lr.number(w[1]);
      if (!(t.header.rate >= 10 && t.header.rate <= 100000)) lr.fail("rate must be between 10 and 100000 Hz");
    } else if (w[0] == "device" || w[0] == "scene") {
      lr.expect(w, 2, w[0] == "device" ? "device" : "scene");
      (w[0] == "device" ? t.header.device : t.header.scene) = std::string(w[1]);
    } else if (w[0] == "caps") {
      lr.expect(w, 12, "caps");
      DeviceCapabilities& c = t.header.caps;
      c.max_force = lr.number(w[1]);
      c.max_continuous_force = lr.number(w[2]);
      c.max_stiffness = lr.number(w[3]);
      c.max_force_rate = lr.number(w[4]);
      c.outputs_force = lr.integer<int>(w[5]) != 0;
      for (int i = 0; i < 3; ++i) c.workspace_min[i] = lr.number(w[6 + i]);
      for (int i = 0; i < 3; ++i) c.workspace_max[i] = lr.number(w[9 + i]);
      if (c.max_force < 0 || c.max_force_rate < 0) lr.fail("force limits must not be negative");
    } else if (w[0] == "setup") {
      std::string rest(line.substr(line.find("setup") + 5));
      rest.erase(0, rest.find_first_not_of(" \t"));
      while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ')) rest.pop_back();
      t.header.setup = rest;
    } else if (w[0] == "param") {
      // The name is every word between the keyword and the value ("param max force 2").
      if (w.size() < 3) lr.fail("param needs a name and a value");
      std::string name(w[1]);
      for (std::size_t k = 2; k + 1 < w.size(); ++k) name += " " + std::string(w[k]);
      t.header.params.emplace_back(std::move(name), lr.number(w.back()));
    } else {
      lr.fail("unknown keyword '" + std::string(w[0]) + "'");
    }
  }
  if (!magic) throw ParseError(origin, 0, "empty file, not a haptic trajectory");
  if (t.ticks.empty()) throw ParseError(origin, lr.line, "trajectory has no tick lines");
  return t;
}

void write_trajectory(const std::filesystem::path& path, const Trajectory& t) {
  std::ofstream out(path);
  if (!out) throw Error("cannot create trajectory file '" + path.string() + "'");
  std::string text = format_header(t.header);
  for (const auto& r : t.ticks) append_record(text, r);
  out << text;
  if (!out.flush()) throw Error("failed writing trajectory file '" + path.string() + "'");
}

Trajectory circle_trajectory(double seconds, double rate, double radius, double turns, double depth) {
  Trajectory t;
  t.header.rate = rate;
  t.header.device = "generated";
  const auto n = static_cast<std::uint64_t>(std::max(1.0, std::round(seconds * rate)));
  const double omega = 2 * M_PI * turns / seconds;
  t.ticks.resize(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    const double time = static_cast<double>(i) / rate;
    TickRecord& r = t.ticks[i];
    r.tick = i;
    r.position[0] = radius * std::cos(omega * time);
    r.position[1] = radius * std::sin(omega * time);
    r.position[2] = -depth;
    r.velocity[0] = -radius * omega * std::sin(omega * time);
    r.velocity[1] = radius * omega * std::cos(omega * time);
    for (int k = 0; k < 3; ++k) r.target[k] = r.position[k];
  }
  return t;
}

TrajectoryRecorder::TrajectoryRecorder(const std::filesystem::path& path, const TrajectoryHeader& header)
    : path_(path), file_(path) {
  if (!file_) throw Error("cannot create recording file '" + path.string() + "'");
  file_ << format_header(header);
  writer_ = std::thread([this] { drain(); });
}

TrajectoryRecorder::~TrajectoryRecorder() {
  try {
    close();
  } catch (...) {  // destructor: the error was already reportable through close()
  }
}

bool TrajectoryRecorder::push(const TickRecord& r) {
  if (queue_.try_push(r)) return true;
  dropped_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

void TrajectoryRecorder::drain() {
  std::string text;
  text.reserve(1 << 16);
  for (;;) {
    const bool last = stop_.load(std::memory_order_acquire);
    while (auto r = queue_.try_pop()) {
      append_record(text, *r);
      written_.fetch_add(1, std::memory_order_relaxed);
      if (text.size() > (1 << 16) - 256) {
        file_ << text;
        text.clear();
      }
    }
    file_ << text;
    text.clear();
    if (last) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  file_.flush();
}

void TrajectoryRecorder::close() {
  if (closed_) return;
  closed_ = true;
  stop_.store(true, std::memory_order_release);
  if (writer_.joinable()) writer_.join();
  file_.close();
  if (file_.fail()) throw Error("failed writing recording file '" + path_.string() + "'");
  if (dropped_.load() > 0)
    throw Error("recording '" + path_.string() + "' lost " + std::to_string(dropped_.load()) +
                " ticks: the disk could not keep up");
}

}  // namespace s4d
