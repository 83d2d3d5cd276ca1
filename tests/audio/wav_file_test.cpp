// WAV files: the writer's header fields, a bit-exact round trip, and malformed files refused with a
// sentence (never a crash), including every truncation and random damage of a real file.
#include "audio/wav_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "audio/cue_synth.hpp"
#include "core/error.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> file_bytes(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::string error_of(std::span<const std::uint8_t> bytes) {
  try {
    decode_wav(bytes, "x.wav");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::vector<float> some_cues() {
  const std::vector<CueEvent> cues = {{0.01, CueKind::curve_above, 1}, {0.2, CueKind::curve_below, 1}};
  SynthSettings s;
  s.volume = 1;
  return render_cues(cues, {}, 0.5, s);
}

TEST(WavFile, HeaderIsSixteenBitPcmMono) {
  const std::vector<float> x = {0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 2.0f};
  const std::vector<std::uint8_t> b = encode_wav(x, 44100);
  ASSERT_EQ(b.size(), 44u + 2 * x.size());
  EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "RIFF");
  EXPECT_EQ(b[4] | b[5] << 8, int(b.size() - 8));
  EXPECT_EQ(std::string(b.begin() + 8, b.begin() + 16), "WAVEfmt ");
  EXPECT_EQ(b[20], 1);                          // PCM
  EXPECT_EQ(b[22], 1);                          // mono
  EXPECT_EQ(b[24] | b[25] << 8 | b[26] << 16, 44100);
  EXPECT_EQ(b[34], 16);                         // bits
  EXPECT_EQ(std::string(b.begin() + 36, b.begin() + 40), "data");
  const WavData d = decode_wav(b, "x.wav");
  EXPECT_EQ(d.pcm, (std::vector<std::int16_t>{0, 16384, -16384, 32767, -32767, 32767}));  // 2.0 clamps
  EXPECT_EQ(quantise_sample(-1.5f), -32768);
  EXPECT_EQ(quantise_sample(std::nanf("")), 0);
}

TEST(WavFile, RoundTripIsBitExact) {
  const std::vector<float> x = some_cues();
  const fs::path p = fs::temp_directory_path() / "s4d_wav_round_trip.wav";
  write_wav(p, x, kAudioSampleRate);
  const WavData d = read_wav(p);
  EXPECT_EQ(d.sample_rate, kAudioSampleRate);
  EXPECT_EQ(d.channels, 1);
  ASSERT_EQ(d.pcm.size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(d.pcm[i], quantise_sample(x[i])) << i;
  // What was read, written again, is the same file byte for byte (the quantisation is idempotent).
  const fs::path q = fs::temp_directory_path() / "s4d_wav_round_trip2.wav";
  write_wav(q, d.samples(), d.sample_rate);
  EXPECT_EQ(file_bytes(p), file_bytes(q));
  EXPECT_NEAR(d.seconds(), 0.5, 1e-4);
  fs::remove(p);
  fs::remove(q);
}

TEST(WavFile, UnknownChunksAreSkipped) {
  std::vector<std::uint8_t> b = encode_wav(std::vector<float>{0.25f, -0.25f}, 8000);
  // Insert an odd-sized LIST chunk (padded) between fmt and data, and fix the RIFF size.
  const std::vector<std::uint8_t> list = {'L', 'I', 'S', 'T', 3, 0, 0, 0, 'a', 'b', 'c', 0};
  b.insert(b.begin() + 36, list.begin(), list.end());
  const std::uint32_t riff = std::uint32_t(b.size() - 8);
  for (int i = 0; i < 4; ++i) b[4 + i] = std::uint8_t(riff >> (8 * i));
  const WavData d = decode_wav(b, "x.wav");
  EXPECT_EQ(d.pcm, (std::vector<std::int16_t>{8192, -8192}));
  EXPECT_EQ(d.sample_rate, 8000);
}

TEST(WavFile, MalformedFilesAreRefusedWithAMessage) {
  const std::vector<std::uint8_t> good = encode_wav(some_cues(), kAudioSampleRate);
  // Truncated: the RIFF size promises more than the file holds.
  std::vector<std::uint8_t> cut(good.begin(), good.begin() + good.size() / 2);
  EXPECT_NE(error_of(cut).find("x.wav: truncated"), std::string::npos) << error_of(cut);
  // The RIFF size made consistent with the cut: now the data chunk is what is short.
  const std::uint32_t riff = std::uint32_t(cut.size() - 8);
  for (int i = 0; i < 4; ++i) cut[4 + i] = std::uint8_t(riff >> (8 * i));
  EXPECT_NE(error_of(cut).find("chunk 'data' says"), std::string::npos) << error_of(cut);
  // Garbage.
  const std::vector<std::uint8_t> junk = {'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd', '!', '!'};
  EXPECT_NE(error_of(junk).find("is not a WAV file"), std::string::npos);
  EXPECT_NE(error_of({}).find("is not a WAV file"), std::string::npos);
  // 8-bit samples.
  std::vector<std::uint8_t> eight = good;
  eight[34] = 8;
  EXPECT_NE(error_of(eight).find("8-bit samples; only 16-bit PCM"), std::string::npos) << error_of(eight);
  // Float format.
  std::vector<std::uint8_t> fl = good;
  fl[20] = 3;
  EXPECT_NE(error_of(fl).find("not PCM"), std::string::npos);
  // No data chunk at all.
  std::vector<std::uint8_t> head(good.begin(), good.begin() + 36);
  head[4] = 28;
  head[5] = head[6] = head[7] = 0;
  EXPECT_NE(error_of(head).find("no data chunk"), std::string::npos) << error_of(head);
  // A missing file.
  try {
    read_wav("/nonexistent/s4d.wav");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open /nonexistent/s4d.wav"), std::string::npos);
  }
}

TEST(WavFile, EveryTruncationAndRandomDamageIsAnErrorNotACrash) {
  const std::vector<std::uint8_t> good = encode_wav(std::vector<float>(50, 0.1f), 22050);
  for (std::size_t n = 0; n < good.size(); ++n) {
    const std::vector<std::uint8_t> cut(good.begin(), good.begin() + n);
    EXPECT_FALSE(error_of(cut).empty()) << "accepted a file cut at " << n << " bytes";
  }
  std::mt19937 rng(7);
  int refused = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::uint8_t> b = good;
    for (int k = 0; k < 3; ++k) b[rng() % 44] = std::uint8_t(rng());  // damage the header
    try {
      const WavData d = decode_wav(b, "x.wav");
      EXPECT_EQ(d.pcm.size() % d.channels, 0u);
    } catch (const Error&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 500);
}

}  // namespace
}  // namespace s4d
