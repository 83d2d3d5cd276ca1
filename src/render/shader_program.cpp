// GLSL compile and link with the driver's log in the error (see shader_program.hpp).
#include "render/shader_program.hpp"

#include "render/gl.hpp"

#include <algorithm>
#include <vector>

#include "core/error.hpp"

namespace s4d {

namespace {

// The shaders are written once in GLSL 3.30 core; OpenGL ES 3.0 (WebGL2) takes them as GLSL ES
// 3.00 with the precisions ES asks for, the rest of the language being the same for our shaders.
std::string for_this_gl(const char* source) {
  std::string text = source;
#ifdef S4D_GLES
  const std::string desktop = "#version 330 core";
  if (text.rfind(desktop, 0) == 0)
    text = "#version 300 es\nprecision highp float;\nprecision highp int;" + text.substr(desktop.size());
#endif
  return text;
}

GLuint compile(const std::string& name, GLenum type, const char* glsl) {
  const std::string text = for_this_gl(glsl);
  const char* source = text.c_str();
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(s, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(s);
    throw Error(name + ": " + (type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                " shader does not compile: " + log.data());
  }
  return s;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const char* vertex_source,
                             const char* fragment_source) {
  const GLuint vs = compile(name, GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);  // the program keeps them alive while attached
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(program_);
    program_ = 0;
    throw Error(name + ": program does not link: " + log.data());
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }

int ShaderProgram::uniform(const char* name) const {
  const GLint loc = glGetUniformLocation(program_, name);
  if (loc < 0) throw Error(std::string("shader has no active uniform '") + name + "'");
  return loc;
}

}  // namespace s4d
