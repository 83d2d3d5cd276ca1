// A linked GLSL program (vertex + fragment) with compile/link errors turned into s4d::Error.
#pragma once
#include <string>

namespace s4d {

// Needs a current OpenGL 3.3 core context for its whole life.
class ShaderProgram {
 public:
  // `name` labels error messages, e.g. "surface shader".
  ShaderProgram(const std::string& name, const char* vertex_source, const char* fragment_source);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  unsigned id() const { return program_; }
  // Location of a uniform; throws s4d::Error if the program has no active uniform of that name,
  // so a typo in a uniform name fails loudly instead of silently drawing wrong.
  int uniform(const char* name) const;

 private:
  unsigned program_ = 0;
};

}  // namespace s4d
