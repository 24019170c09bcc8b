#pragma once
// Owning handles of OpenGL objects: each deletes its object when it is destroyed or reset, and
// moves but does not copy. Created with the GL 4.5 direct-state-access calls (glCreate*), so an
// object exists (and is typed) as soon as it is made. Needs a current context for make/reset.

#include <utility>

#include <epoxy/gl.h>

namespace gfield {

/// How each kind of GL object is created and deleted.
struct GlTextureKind {
  static GLuint create(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct GlBufferKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct GlFramebufferKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct GlRenderbufferKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateRenderbuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct GlVertexArrayKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct GlQueryKind {
  static GLuint create(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

/// One GL object of kind `Kind`; 0 when empty.
template <class Kind>
class GlObject {
 public:
  GlObject() = default;
  ~GlObject() { reset(); }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  /// Deletes the object held (if any) and creates a new one (`args`: the texture target).
  template <class... Args>
  GLuint make(Args... args) {
    reset();
    id_ = Kind::create(args...);
    return id_;
  }
  void reset() {
    if (id_ != 0)
      Kind::destroy(id_);
    id_ = 0;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
};

using GlTexture = GlObject<GlTextureKind>;
using GlBuffer = GlObject<GlBufferKind>;
using GlFramebuffer = GlObject<GlFramebufferKind>;
using GlRenderbuffer = GlObject<GlRenderbufferKind>;
using GlVertexArray = GlObject<GlVertexArrayKind>;
using GlQuery = GlObject<GlQueryKind>;

}  // namespace gfield
