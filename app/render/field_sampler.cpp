#include "render/field_sampler.h"

#include <algorithm>

namespace ms {

namespace {

// Invocations per dispatch: a long list becomes several dispatches, so
// that no single one runs long enough for a desktop driver's watchdog.
constexpr std::size_t kFieldChunk = std::size_t{1} << 20;

// map() calls per point: its value and a 4-tap gradient. (Bricks and
// cells take one per value; an edge says how many it took.)
constexpr std::uint64_t kPointEvaluations = 5;

}  // namespace

FieldSampler::FieldSampler(const Program& prog, const FieldGrid& grid, const FieldClip& clip, float time)
    : prog_(prog) {
  glGenBuffers(4, buffers_);
  prog_.set("uFieldOrigin", grid.origin);
  prog_.set("uFieldVoxel", grid.voxel);
  prog_.set("uClipKind", clip.sphere ? 1 : 2);
  prog_.set("uClipA", clip.a);
  prog_.set("uClipB", clip.b);
  prog_.set("uFieldPlanes", clip.planes ? 1 : 0);
  prog_.set("uTime", time);
}

FieldSampler::~FieldSampler() { glDeleteBuffers(4, buffers_); }

void FieldSampler::upload(GLuint buffer, const void* data, std::size_t bytes) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 16)), data,
               GL_STATIC_DRAW);
}

void FieldSampler::read(GLuint buffer, void* data, std::size_t bytes) {
  if (bytes == 0) return;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  readback_ += bytes;
}

void FieldSampler::run(int mode, std::size_t count) {
  glUseProgram(prog_.id());
  prog_.set("uFieldMode", mode);
  for (int i = 0; i < 4; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i == 3 ? 8 : i, buffers_[i]);
  for (std::size_t base = 0; base < count; base += kFieldChunk) {
    const std::size_t n = std::min(kFieldChunk, count - base);
    prog_.set("uFieldBase", static_cast<int>(base));
    prog_.set("uFieldCount", static_cast<int>(n));
    glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

std::vector<float> FieldSampler::cells(const std::vector<glm::ivec4>& cells) {
  std::vector<float> out(cells.size());
  if (cells.empty()) return out;
  upload(buffers_[0], cells.data(), cells.size() * sizeof(glm::ivec4));
  upload(buffers_[1], nullptr, out.size() * sizeof(float));
  run(1, cells.size());
  read(buffers_[1], out.data(), out.size() * sizeof(float));
  evaluations_ += cells.size();
  return out;
}

std::vector<float> FieldSampler::bricks(const std::vector<glm::ivec3>& first_voxels, int brick) {
  const std::size_t per = static_cast<std::size_t>(brick + 1) * (brick + 1) * (brick + 1);
  std::vector<float> out(first_voxels.size() * per);
  if (out.empty()) return out;
  std::vector<glm::ivec4> in(first_voxels.size());
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = glm::ivec4(first_voxels[i], 0);
  upload(buffers_[0], in.data(), in.size() * sizeof(glm::ivec4));
  upload(buffers_[1], nullptr, out.size() * sizeof(float));
  prog_.set("uBrick", brick);
  run(0, out.size());
  read(buffers_[1], out.data(), out.size() * sizeof(float));
  evaluations_ += out.size();
  return out;
}

std::vector<glm::vec4> FieldSampler::edges(const std::vector<glm::ivec4>& edges) {
  std::vector<glm::vec4> out(edges.size());
  if (out.empty()) return out;
  upload(buffers_[0], edges.data(), edges.size() * sizeof(glm::ivec4));
  upload(buffers_[1], nullptr, out.size() * sizeof(float));
  upload(buffers_[2], nullptr, out.size() * sizeof(glm::vec4));
  run(2, edges.size());
  read(buffers_[2], out.data(), out.size() * sizeof(glm::vec4));
  std::vector<float> calls(out.size());
  read(buffers_[1], calls.data(), calls.size() * sizeof(float));
  for (float c : calls) evaluations_ += static_cast<std::uint64_t>(c);
  return out;
}

std::vector<FieldPoint> FieldSampler::points(const std::vector<glm::vec3>& points, bool gradient) {
  std::vector<FieldPoint> out(points.size());
  if (out.empty()) return out;
  std::vector<glm::vec4> in(points.size());
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = glm::vec4(points[i], 1.0f);
  upload(buffers_[3], in.data(), in.size() * sizeof(glm::vec4));
  upload(buffers_[1], nullptr, out.size() * sizeof(float));
  upload(buffers_[2], nullptr, out.size() * sizeof(glm::vec4));
  run(gradient ? 3 : 4, out.size());
  std::vector<glm::vec4> v(out.size());
  std::vector<float> m(out.size());
  read(buffers_[2], v.data(), v.size() * sizeof(glm::vec4));
  read(buffers_[1], m.data(), m.size() * sizeof(float));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {glm::vec3(v[i]), v[i].w, static_cast<int>(m[i] + 0.5f)};
  evaluations_ += out.size() * (gradient ? kPointEvaluations : 1);
  return out;
}

}  // namespace ms
