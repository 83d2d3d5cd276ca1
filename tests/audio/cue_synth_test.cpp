// The cue synthesiser: onsets at the right samples, over/under (above/below) told apart by their
// measured pitch and contour, mute, volume, the depth tone, and bad input refused.
#include "audio/cue_synth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "audio/audio_measure.hpp"
#include "core/error.hpp"

namespace s4d {
namespace {

constexpr int kRate = kAudioSampleRate;

std::vector<float> one_cue(CueKind kind, float volume = 1) {
  const CueEvent e{0, kind, 1};
  SynthSettings s;
  s.volume = volume;
  return render_cues(std::span(&e, 1), {}, 0.3, s);
}

TEST(CueSynth, OnsetsLandOnTheirSampleIndices) {
  // Times off the sample grid: onset = round(t * rate).
  const std::vector<CueEvent> cues = {{0.6001, CueKind::curve_below, 1},
                                      {0.123456, CueKind::curve_above, 1},
                                      {0.35, CueKind::grab, 1}};
  SynthSettings s;
  s.volume = 0.5f;
  const std::vector<float> pcm = render_cues(cues, {}, 1.0, s);
  ASSERT_EQ(pcm.size(), std::size_t(kRate));
  std::vector<bool> covered(pcm.size(), false);
  for (const CueEvent& e : cues) {
    const long n0 = std::lround(e.time * kRate);
    const long len = long(std::ceil(cue_duration(e.kind) * kRate));
    for (long k = 0; k < len; ++k) {
      // The only voice sounding: exactly the cue's own sample times the volume.
      ASSERT_EQ(pcm[n0 + k], 0.5f * cue_sample(e.kind, k)) << cue_name(e.kind) << " sample " << k;
      covered[n0 + k] = true;
    }
    EXPECT_NE(pcm[n0 + 3], 0.0f) << "sound starts at the onset";
  }
  EXPECT_EQ(std::lround(0.123456 * kRate), 5444);
  for (std::size_t i = 0; i < pcm.size(); ++i)
    if (!covered[i]) {
      ASSERT_EQ(pcm[i], 0.0f) << "silence between cues, sample " << i;
    }
}

TEST(CueSynth, OverAndUnderDifferInPitchAndContour) {
  for (auto [high, low] : {std::pair{CueKind::crossing_over, CueKind::crossing_under},
                           std::pair{CueKind::curve_above, CueKind::curve_below}}) {
    const std::vector<float> a = one_cue(high), b = one_cue(low);
    const double fa = test::dominant_frequency(a, kRate), fb = test::dominant_frequency(b, kRate);
    EXPECT_GT(fa, 1200) << cue_name(high);
    EXPECT_LT(fb, 220) << cue_name(low);
    EXPECT_GT(fa / fb, 5) << "three octaves apart, not merely unequal";
    // Contour: the ping rises E6 -> A6, the thud falls G3 -> D3.
    const double a1 = test::dominant_frequency(test::window(a, 0.005, 0.065, kRate), kRate, 1000, 2000, 2);
    const double a2 = test::dominant_frequency(test::window(a, 0.075, 0.175, kRate), kRate, 1000, 2000, 2);
    EXPECT_NEAR(a1, 1318.5, 20);
    EXPECT_NEAR(a2, 1760, 15);
    const double b1 = test::dominant_frequency(test::window(b, 0.0, 0.08, kRate), kRate, 100, 300, 1);
    const double b2 = test::dominant_frequency(test::window(b, 0.14, 0.22, kRate), kRate, 100, 300, 1);
    EXPECT_GT(b1, b2 + 15) << "falling";
    // Timbre: the ping carries a second harmonic, the thud is a pure tone.
    const auto ha = test::window(a, 0.075, 0.175, kRate);
    EXPECT_GT(test::goertzel_power(ha, 2 * 1760, kRate), 0.05 * test::goertzel_power(ha, 1760, kRate));
    const auto hb = test::window(b, 0.0, 0.1, kRate);
    EXPECT_LT(test::goertzel_power(hb, 2 * b1, kRate), 1e-3 * test::goertzel_power(hb, b1, kRate));
  }
}

TEST(CueSynth, GrabRisesAndReleaseFalls) {
  const std::vector<float> g = one_cue(CueKind::grab), r = one_cue(CueKind::release);
  const auto early = [](const std::vector<float>& x) {
    return test::dominant_frequency(test::window(x, 0.0, 0.02, kRate), kRate, 300, 1200, 5);
  };
  const auto late = [](const std::vector<float>& x) {
    return test::dominant_frequency(test::window(x, 0.03, 0.05, kRate), kRate, 300, 1200, 5);
  };
  EXPECT_GT(late(g), early(g) + 200);
  EXPECT_LT(late(r), early(r) - 200);
}

TEST(CueSynth, MuteGivesSilence) {
  const std::vector<CueEvent> cues = {{0.0, CueKind::crossing_over, 1}, {0.1, CueKind::release, 1}};
  const std::vector<DepthSample> depth = {{0.0, 0.2}, {0.2, 0.9}};
  SynthSettings s;
  s.mute = true;
  s.depth_tone = true;
  const std::vector<float> pcm = render_cues(cues, depth, 0.5, s);
  ASSERT_EQ(pcm.size(), std::size_t(0.5 * kRate));
  for (float v : pcm) ASSERT_EQ(v, 0.0f);
  s.mute = false;
  EXPECT_GT(test::peak(render_cues(cues, depth, 0.5, s)), 0.1) << "the same input, unmuted, sounds";
}

TEST(CueSynth, VolumeScalesTheAmplitude) {
  const std::vector<CueEvent> cues = {{0.0, CueKind::curve_above, 1}, {0.05, CueKind::curve_below, 1}};
  SynthSettings quiet, loud;
  quiet.volume = 0.25f;
  loud.volume = 0.5f;
  const std::vector<float> q = render_cues(cues, {}, 0.4, quiet), l = render_cues(cues, {}, 0.4, loud);
  ASSERT_EQ(q.size(), l.size());
  for (std::size_t i = 0; i < q.size(); ++i) ASSERT_EQ(l[i], 2 * q[i]) << i;  // scaling by 2 is exact
  EXPECT_NEAR(test::peak(l) / test::peak(q), 2.0, 1e-6);
  EXPECT_GT(test::peak(q), 0.05);
  // Overlapping cues add: the mix is the sum of the two cues rendered alone.
  const std::vector<float> a = render_cues(std::span(&cues[0], 1), {}, 0.4, loud);
  const std::vector<float> b = render_cues(std::span(&cues[1], 1), {}, 0.4, loud);
  for (std::size_t i = 0; i < l.size(); ++i) ASSERT_NEAR(l[i], a[i] + b[i], 1e-6) << i;
}

TEST(CueSynth, DepthToneFollowsTheDepthAndIsOffByDefault) {
  const std::vector<DepthSample> depth = {{0.0, 0.0}, {0.5, 1.0}};
  SynthSettings s;
  const std::vector<float> off = render_cues({}, depth, 1.0, s);
  for (float v : off) ASSERT_EQ(v, 0.0f) << "no tone unless asked for";
  s.depth_tone = true;
  const std::vector<float> on = render_cues({}, depth, 1.0, s);
  EXPECT_NEAR(test::dominant_frequency(test::window(on, 0.1, 0.5, kRate), kRate, 100, 1200, 2), 220, 3);
  EXPECT_NEAR(test::dominant_frequency(test::window(on, 0.6, 1.0, kRate), kRate, 100, 1200, 2), 880, 3);
  EXPECT_NEAR(depth_tone_frequency(0.5), 440, 1e-9);
  EXPECT_LT(test::peak(on), 0.2) << "the tone stays below the cues";
  // No click when the pitch jumps: the glide keeps neighbouring samples close.
  double jump = 0;
  for (std::size_t i = 1; i < on.size(); ++i) jump = std::max(jump, double(std::abs(on[i] - on[i - 1])));
  EXPECT_LT(jump, 0.8 * 0.12 * 2 * 3.1416 * 880 / kRate + 1e-3);
}

TEST(CueSynth, MixerReplacesTheOldestVoiceWhenFull) {
  CueMixer m;
  for (int i = 0; i < CueMixer::kMaxVoices + 5; ++i) m.start(CueKind::grab);
  EXPECT_EQ(m.active_voices(), CueMixer::kMaxVoices);
  std::vector<float> buf(std::size_t(0.06 * kRate));
  m.mix(buf);
  EXPECT_EQ(m.active_voices(), 0) << "every voice ends after its cue";
}

TEST(CueSynth, BadInputIsRefusedWithASentence) {
  const CueEvent nan_cue{std::nan(""), CueKind::grab, 1};
  EXPECT_THROW(render_cues(std::span(&nan_cue, 1), {}, 1, {}), Error);
  const CueEvent neg{-1, CueKind::grab, 1};
  try {
    render_cues(std::span(&neg, 1), {}, 1, {});
    FAIL() << "a negative time was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("finite and >= 0"), std::string::npos) << e.what();
  }
  SynthSettings s;
  s.sample_rate = 100;
  EXPECT_THROW(render_cues({}, {}, 1, s), Error);
  s = {};
  s.volume = 3;
  EXPECT_THROW(render_cues({}, {}, 1, s), Error);
  const DepthSample bad{0, std::nan("")};
  EXPECT_THROW(render_cues({}, std::span(&bad, 1), 1, {}), Error);
  EXPECT_THROW(render_cues({}, {}, 1e6, {}), Error) << "absurd length";
  EXPECT_TRUE(render_cues({}, {}, 0, {}).empty());
  // A NaN gain or depth in the live mixer is ignored, never propagated.
  CueMixer m;
  m.set_depth(std::nan(""));
  m.set_volume(std::nan(""));
  m.set_depth_tone(true);
  m.start(CueKind::curve_above, std::nanf(""));
  std::vector<float> buf(4096);
  m.mix(buf);
  for (float v : buf) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace s4d
