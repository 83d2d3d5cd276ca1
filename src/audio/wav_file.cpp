// RIFF/WAVE: "RIFF" size "WAVE", then chunks (id, little-endian size, payload, pad to even). We write
// "fmt " (PCM, 16 bits) and "data"; the reader skips chunks it does not know (LIST, fact, ...).
#include "audio/wav_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/error.hpp"

namespace s4d {

namespace {

constexpr std::uint64_t kMaxWavBytes = std::uint64_t(1) << 31;  // 2 GiB: RIFF's 32-bit sizes, and sanity

void put_u32(std::vector<std::uint8_t>& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void put_u16(std::vector<std::uint8_t>& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v));
  b.push_back(static_cast<std::uint8_t>(v >> 8));
}
void put_id(std::vector<std::uint8_t>& b, const char* id) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(id[i]));
}

std::uint32_t get_u32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
std::uint16_t get_u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }

// A chunk id as text for messages (non-printable bytes as '?').
std::string id_text(const std::uint8_t* p) {
  std::string s(4, '?');
  for (int i = 0; i < 4; ++i)
    if (p[i] >= 32 && p[i] < 127) s[i] = static_cast<char>(p[i]);
  return s;
}

}  // namespace

std::vector<float> WavData::samples() const {
  std::vector<float> out(pcm.size());
  for (std::size_t i = 0; i < pcm.size(); ++i) out[i] = static_cast<float>(pcm[i] / 32767.0);
  return out;
}

std::int16_t quantise_sample(float x) {
  if (!std::isfinite(x)) return 0;
  const double v = std::round(static_cast<double>(x) * 32767.0);
  return static_cast<std::int16_t>(std::clamp(v, -32768.0, 32767.0));
}

std::vector<std::uint8_t> encode_wav(std::span<const float> samples, int sample_rate) {
  if (sample_rate < 1 || sample_rate > 384000)
    throw Error("WAV sample rate " + std::to_string(sample_rate) + " Hz is out of range [1, 384000]");
  const std::uint64_t data_bytes = 2 * std::uint64_t(samples.size());
  if (data_bytes + 44 > kMaxWavBytes) throw Error("too many samples for a WAV file (over 2 GiB)");
  std::vector<std::uint8_t> b;
  b.reserve(44 + data_bytes);
  put_id(b, "RIFF");
  put_u32(b, static_cast<std::uint32_t>(36 + data_bytes));
  put_id(b, "WAVE");
  put_id(b, "fmt ");
  put_u32(b, 16);
  put_u16(b, 1);  // PCM
  put_u16(b, 1);  // mono
  put_u32(b, static_cast<std::uint32_t>(sample_rate));
  put_u32(b, static_cast<std::uint32_t>(sample_rate) * 2);  // bytes per second
  put_u16(b, 2);                                           // bytes per frame
  put_u16(b, 16);                                          // bits per sample
  put_id(b, "data");
  put_u32(b, static_cast<std::uint32_t>(data_bytes));
  for (float x : samples) put_u16(b, static_cast<std::uint16_t>(quantise_sample(x)));
  return b;  // even length always: no pad byte
}

void write_wav(const std::filesystem::path& path, std::span<const float> samples, int sample_rate) {
  const std::vector<std::uint8_t> bytes = encode_wav(samples, sample_rate);
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw Error("cannot create " + path.string());
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  f.close();
  if (!f) throw Error("writing " + path.string() + " failed (disk full?)");
}

WavData decode_wav(std::span<const std::uint8_t> bytes, const std::string& name) {
  const std::size_t n = bytes.size();
  const std::uint8_t* b = bytes.data();
  if (n < 12 || std::memcmp(b, "RIFF", 4) != 0 || std::memcmp(b + 8, "WAVE", 4) != 0)
    throw Error(name + " is not a WAV file (it does not start with RIFF....WAVE)");
  const std::uint64_t riff_end = 8 + std::uint64_t(get_u32(b + 4));
  if (riff_end > n)
    throw Error(name + ": truncated: the RIFF header announces " + std::to_string(riff_end) +
                " bytes but the file has " + std::to_string(n));
  WavData out;
  bool have_fmt = false, have_data = false;
  int bits = 0;
  std::size_t pos = 12;
  while (pos + 8 <= riff_end && !have_data) {
    const std::string id = id_text(b + pos);
    const std::uint64_t size = get_u32(b + pos + 4);
    const std::size_t body = pos + 8;
    if (body + size > riff_end)
      throw Error(name + ": truncated: chunk '" + id + "' says " + std::to_string(size) + " bytes but " +
                  std::to_string(riff_end - body) + " remain");
    if (id == "fmt ") {
      if (size < 16) throw Error(name + ": the fmt chunk is " + std::to_string(size) + " bytes, fewer than 16");
      const int format = get_u16(b + body);
      out.channels = get_u16(b + body + 2);
      out.sample_rate = static_cast<int>(std::min<std::uint32_t>(get_u32(b + body + 4), 1u << 30));
      const int block = get_u16(b + body + 12);
      bits = get_u16(b + body + 14);
      if (format != 1)
        throw Error(name + ": sample format " + std::to_string(format) + " is not PCM (1); only 16-bit PCM is read");
      if (bits != 16) throw Error(name + ": " + std::to_string(bits) + "-bit samples; only 16-bit PCM is read");
      if (out.channels < 1) throw Error(name + ": the fmt chunk gives no channels");
      if (block != 2 * out.channels)
        throw Error(name + ": block size " + std::to_string(block) + " does not match " +
                    std::to_string(out.channels) + " channel(s) of 16 bits");
      if (out.sample_rate < 1) throw Error(name + ": the sample rate is 0");
      have_fmt = true;
    } else if (id == "data") {
      if (!have_fmt) throw Error(name + ": the data chunk comes before any fmt chunk");
      if (size % (2 * std::uint64_t(out.channels)) != 0)
        throw Error(name + ": the data chunk's " + std::to_string(size) + " bytes are not whole frames of " +
                    std::to_string(out.channels) + " channel(s) of 16 bits");
      out.pcm.resize(size / 2);
      for (std::size_t i = 0; i < out.pcm.size(); ++i)
        out.pcm[i] = static_cast<std::int16_t>(get_u16(b + body + 2 * i));
      have_data = true;
    }
    pos = body + size + (size & 1);  // chunks are padded to an even length
  }
  if (!have_fmt) throw Error(name + ": no fmt chunk (not a usable WAV file)");
  if (!have_data) throw Error(name + ": no data chunk (truncated?)");
  return out;
}

WavData read_wav(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Error("cannot open " + path.string());
  f.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(std::max<std::streamoff>(0, f.tellg()));
  if (size > kMaxWavBytes) throw Error(path.string() + " is larger than 2 GiB; not read as a WAV file");
  f.seekg(0);
  std::vector<std::uint8_t> bytes(size);
  f.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (!f) throw Error("reading " + path.string() + " failed");
  return decode_wav(bytes, path.string());
}

}  // namespace s4d
