// WAV files of the cues: 16-bit PCM mono RIFF written from float samples, and a strict reader (for
// tests and for checking files) that refuses anything malformed with an Error sentence naming it.
// Hand-written rather than SDL_LoadWAV so it works in builds without SDL2 and says what is wrong.
#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace s4d {

struct WavData {
  int sample_rate = 0;              // Hz
  int channels = 1;
  std::vector<std::int16_t> pcm;    // frames × channels, interleaved
  // pcm as floats in [-1, 1] (s / 32767), the inverse of the writer's quantisation.
  std::vector<float> samples() const;
  double seconds() const { return sample_rate > 0 ? double(pcm.size()) / channels / sample_rate : 0; }
};

// The writer's quantisation of one sample: round(x · 32767), clamped to the int16 range (NaN: 0).
std::int16_t quantise_sample(float x);

// The bytes of a 16-bit PCM mono WAV file of `samples` at `sample_rate` Hz.
std::vector<std::uint8_t> encode_wav(std::span<const float> samples, int sample_rate);
// Writes it; throws Error when the file cannot be written or the rate is not in [1, 384000] Hz.
void write_wav(const std::filesystem::path& path, std::span<const float> samples, int sample_rate);

// Parses WAV bytes (16-bit PCM, any channel count); `name` labels the errors ("x.wav: truncated ...").
WavData decode_wav(std::span<const std::uint8_t> bytes, const std::string& name);
// Reads a WAV file; throws Error when it cannot be read or is malformed.
WavData read_wav(const std::filesystem::path& path);

}  // namespace s4d
