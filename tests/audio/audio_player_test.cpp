// The SDL2 player: opens with the dummy driver and plays cues on its audio thread; asked for a
// driver that does not exist it says so in one sentence and stays silent without failing.
#include "audio/audio_player.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <thread>

namespace s4d {
namespace {

// Waits up to 3 s for pred().
template <typename Pred>
bool eventually(Pred pred) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return pred();
}

TEST(AudioPlayer, DummyDriverPlaysCues) {
  setenv("SDL_AUDIODRIVER", "dummy", 1);  // no sound card in CI: SDL's dummy device still runs the callback
  AudioPlayer player;
  if (player.status().find("no SDL2") != std::string::npos) GTEST_SKIP() << player.status();
  ASSERT_TRUE(player.available()) << player.status();
  EXPECT_NE(player.status().find("dummy"), std::string::npos) << player.status();
  player.play(CueKind::curve_above);
  player.play(CueKind::curve_below, 0.5f);
  EXPECT_TRUE(eventually([&] { return player.cues_started() == 2; })) << player.cues_started();
  const std::uint64_t f0 = player.frames_rendered();
  EXPECT_TRUE(eventually([&] { return player.frames_rendered() > f0 + 4096; })) << "the callback keeps running";
  // Live settings, from this (the "UI") thread while the callback runs.
  player.set_volume(0.3f);
  EXPECT_FLOAT_EQ(player.volume(), 0.3f);
  player.set_volume(7);
  EXPECT_FLOAT_EQ(player.volume(), 1.0f);
  player.set_volume(std::nanf(""));
  EXPECT_FLOAT_EQ(player.volume(), 1.0f);
  player.set_mute(true);
  EXPECT_TRUE(player.muted());
  player.set_depth_tone(true);
  player.set_depth(0.7);
  for (int i = 0; i < 200; ++i) player.play(CueKind::grab);  // a burst: some may be dropped, none crash
  EXPECT_TRUE(eventually([&] { return player.cues_started() + player.cues_dropped() == 202; }));
  unsetenv("SDL_AUDIODRIVER");
}

TEST(AudioPlayer, ANamedDriverIsUsed) {
  AudioPlayerOptions o;
  o.driver = "dummy";
  AudioPlayer player(o);
  if (player.status().find("no SDL2") != std::string::npos) GTEST_SKIP() << player.status();
  ASSERT_TRUE(player.available()) << player.status();
  EXPECT_EQ(player.status(), "sound through SDL2 (dummy, 44100 Hz)");
}

TEST(AudioPlayer, AMissingDriverIsASentenceNotAFailure) {
  AudioPlayerOptions o;
  o.driver = "no-such-driver";
  AudioPlayer player(o);
  EXPECT_FALSE(player.available());
  const std::string& s = player.status();
  EXPECT_EQ(s.rfind("no sound: ", 0), 0u) << s;
  EXPECT_NE(s.find("cues are silent"), std::string::npos) << s;
  EXPECT_EQ(s.find('\n'), std::string::npos) << "one sentence";
  if (s.find("no SDL2") == std::string::npos) {
    EXPECT_NE(s.find("'no-such-driver'"), std::string::npos) << s;
  }
  // Everything still works, silently.
  player.play(CueKind::crossing_over);
  player.set_volume(0.5f);
  player.set_mute(true);
  EXPECT_EQ(player.cues_started(), 0u);
  EXPECT_EQ(player.frames_rendered(), 0u);
  // And a later player with a real driver is not spoiled by the failed one.
  o.driver = "dummy";
  AudioPlayer after(o);
  if (after.status().find("no SDL2") == std::string::npos) {
    EXPECT_TRUE(after.available()) << after.status();
  }
}

}  // namespace
}  // namespace s4d
