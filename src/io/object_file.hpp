// One object file of any supported format, chosen by extension; shared by load_object and scenes.
#pragma once
#include <filesystem>
#include <string>

#include "shape/shape.hpp"

namespace s4d {

// .off/.4off/.noff -> surface; .vect/.4vect -> curve (VECT); .txt/.xyz/.curve -> text curve.
// Case-insensitive. Throws Error for an unknown extension, ParseError for a malformed file.
Shape read_shape_file(const std::filesystem::path& path);
// True when read_shape_file knows the extension.
bool is_shape_file_extension(const std::filesystem::path& path);
// Writes a shape in the format its extension names; the shape's kind must fit (a surface into
// .off/.4off, a curve into .vect/.4vect/.curve/...). Throws Error otherwise.
void write_shape_file(const Shape& shape, const std::filesystem::path& path);
// The extension save_scene uses for geometry with no other home: .off, .4off or .curve.
std::string native_extension(const Shape& shape);

}  // namespace s4d
