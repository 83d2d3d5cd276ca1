// Format dispatch by file extension, and the object offset.
#include "io/object_file.hpp"

#include <algorithm>
#include <cctype>

#include "core/error.hpp"
#include "io/curve_text.hpp"
#include "io/off.hpp"
#include "io/vect.hpp"

namespace s4d {

namespace {

enum class Format { kUnknown, kOff, kVect, kCurveText };

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

Format format_of(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".off" || ext == ".4off" || ext == ".noff") return Format::kOff;
  if (ext == ".vect" || ext == ".4vect") return Format::kVect;
  if (ext == ".txt" || ext == ".xyz" || ext == ".curve") return Format::kCurveText;
  return Format::kUnknown;
}

template <typename T>
void translate(T& points, const auto& offset) {
  for (auto& p : points) p += offset;
}

}  // namespace

bool is_shape_file_extension(const std::filesystem::path& path) {
  return format_of(path) != Format::kUnknown;
}

Shape read_shape_file(const std::filesystem::path& path) {
  switch (format_of(path)) {
    case Format::kOff: return read_off(path);
    case Format::kVect: return read_vect(path);
    case Format::kCurveText: return read_curve_text(path);
    case Format::kUnknown: break;
  }
  throw Error(path.string() + ": unknown file type '" + path.extension().string() +
              "' (expected .off, .4off, .noff, .vect, .4vect, .txt, .xyz or .curve)");
}

void write_shape_file(const Shape& shape, const std::filesystem::path& path) {
  const Format f = format_of(path);
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        constexpr int D = T::kDim;
        if constexpr (std::is_same_v<T, Surface<D>>) {
          if (f != Format::kOff)
            throw Error("cannot write a surface to " + path.string() + ": use .off or .4off");
          write_off(s, path);
        } else {
          if (f == Format::kVect) {
            write_vect(s, path);
          } else if (f == Format::kCurveText) {
            write_curve_text(s, path);
          } else {
            throw Error("cannot write a curve to " + path.string() + ": use .curve, .txt, .xyz or .vect");
          }
        }
      },
      shape);
}

std::string native_extension(const Shape& shape) {
  if (std::holds_alternative<Surface<3>>(shape)) return ".off";
  if (std::holds_alternative<Surface<4>>(shape)) return ".4off";
  return ".curve";
}

}  // namespace s4d
