#include "render/graph_field.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>

#include <glm/geometric.hpp>

#include "render/graph_field_cache.h"

namespace ms {

namespace {

// `count` words of `buf` from word `first`.
std::vector<std::uint32_t> read_words(GLuint buf, std::size_t first, std::size_t count) {
  std::vector<std::uint32_t> out(count);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(first * sizeof(std::uint32_t)),
                     static_cast<GLsizeiptr>(count * sizeof(std::uint32_t)), out.data());
  return out;
}

template <class T>
void upload(GLuint buf, const std::vector<T>& data, std::size_t extra_bytes = 0) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buf);
  const std::size_t bytes = data.size() * sizeof(T) + extra_bytes;
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes > 0 ? bytes : 16), nullptr, GL_DYNAMIC_COPY);
  if (!data.empty())
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data());
}

}  // namespace

GraphField::GraphField(const GraphParts& parts, std::shared_ptr<const Program> prune, bool disk_cache)
    : parts_(parts), program_(parts.buffers.program.size()), prune_(std::move(prune)) {
  const GraphBuffers& b = parts.buffers;
  const GraphEvalPlan& plan = parts.plan;
  if (plan.pruned() && !prune_) prune_ = std::make_shared<const Program>(Program::Compute{}, parts.prune_src);
  if (!plan.pruned()) prune_.reset();
  glGenBuffers(6, buffers_);
  upload(buffers_[5], std::vector<std::uint32_t>{0u});
  const std::size_t cells = plan.prune ? cell_count(plan) : 0, coarse = plan.prune ? coarse_cell_count(plan) : 0;
  upload(buffers_[0], b.nodes);
  upload(buffers_[1], b.floats);
  upload(buffers_[2], b.program, (program_capacity(plan, b) - b.program.size()) * sizeof(std::uint32_t));
  std::vector<std::uint32_t> head = plan.prune ? grid_header(plan, b) : std::vector<std::uint32_t>{};
  const std::size_t first = head.size();
  head.resize(first + std::max<std::size_t>(cells, 1) * 4, 0u);
  for (std::size_t i = 0; plan.keep_all && i < cells; ++i) head[first + i * 4 + 1] = static_cast<std::uint32_t>(program_);
  upload(buffers_[3], head);
  // The pool's count, three words of padding, then the coarse cells.
  upload(buffers_[4], std::vector<std::uint32_t>((coarse + 1) * 4, 0u));
  bind();
  if (!plan.pruned()) return;
  const auto start = std::chrono::steady_clock::now();
  const PrunedCache cache(b, plan, disk_cache ? parts.prune_src.text : std::string());
  const GLuint kept[3] = {buffers_[2], buffers_[3], buffers_[4]};
  const PrunedSizes sizes{{program_capacity(plan, b) * sizeof(std::uint32_t), head.size() * sizeof(std::uint32_t),
                           (coarse + 1) * 4 * sizeof(std::uint32_t)},
                          pool_base(plan, b) * sizeof(std::uint32_t)};
  std::string refused;
  from_cache_ = cache.load(kept, sizes, &refused);
  if (!from_cache_) run_pass(*prune_);
  pruned_cells_ = cells;
  measure();
  overflowed_whole_ = overflowed_;
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // A refused entry is replaced whatever the pass took: it was kept once,
  // and left as it is it would be refused again on every run.
  const bool written = !from_cache_ && (build_ms_ >= prune_cache_ms() || !refused.empty()) && cache.save(kept, sizes);
  if (!refused.empty())
    cache_note_ = "; the cache's entry " + cache.path().string() + " " + refused + ", not used" +
                  (written ? " and written again" : "");
}

void GraphField::run_pass(const Program& prune, const ReposeCells* only) {
  glUseProgram(prune.id());
  prune.set("uSubset", only ? 1 : 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, buffers_[5]);
  // Per grid level, coarse cells first, then each fine cell from its coarse cell's list.
  for (int grid = 0; grid < kGridLevels; ++grid) {
    prune.set("uGrid", grid);
    const GridLevel& l = plan_.levels[grid];
    for (int level = 0; level < 2; ++level) {
      const std::vector<std::uint32_t>* subset =
          only ? &(level == 0 ? only->coarse : only->fine)[static_cast<std::size_t>(grid)] : nullptr;
      if (subset) {
        if (subset->empty()) continue;
        std::vector<std::uint32_t> list{static_cast<std::uint32_t>(subset->size())};
        list.insert(list.end(), subset->begin(), subset->end());
        upload(buffers_[5], list);
      }
      prune.set("uLevel", level);
      const glm::ivec3 c = coarse_dims(l);
      const std::size_t n = subset ? subset->size()
                            : level == 0 ? static_cast<std::size_t>(c.x) * c.y * c.z
                                         : cell_count(l);
      glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
}

// The fine cells' mean list over level 0, the bounds that rays march (the
// outer levels' cells are larger and rarely visited), and the cells that
// kept their coarse cell's list.
void GraphField::measure() {
  const std::size_t cells = cell_count(plan_);
  fine_ = read_words(buffers_[3], grid_header(plan_, parts_.buffers).size(), cells * 4);
  const std::vector<std::uint32_t>& out = fine_;
  const std::size_t inner = cell_count(plan_.levels[0]);
  double sum = 0.0;
  overflowed_ = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    if (i < inner) sum += out[i * 4 + 1];
    overflowed_ += out[i * 4 + 3] == 1u;
  }
  mean_list_ = inner > 0 ? sum / static_cast<double>(inner) : 0.0;
}

std::size_t GraphField::cells() const { return plan_.prune ? cell_count(plan_) : 0; }

bool GraphField::repose(const GraphParts& next) {
  const GraphBuffers &b = parts_.buffers, &n = next.buffers;
  if (!plan_.pruned() || !prune_ || next.prune_src.text != parts_.prune_src.text || b.program != n.program ||
      b.nodes.size() != n.nodes.size() || b.floats.size() != n.floats.size() || !same_grid(plan_, next.plan))
    return false;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t coarse = coarse_cell_count(plan_);
  // The cells: each holds the field's upper bound on it, and one inside
  // the finer level is all 0. The fine ones as the last pass's measure()
  // read them (nothing has written them since); the coarse ones after the
  // pool's count and padding.
  const std::vector<std::uint32_t> head = read_words(buffers_[4], 0, (coarse + 1) * 4);
  const std::vector<std::uint32_t>& fine = fine_;
  const auto bound = [](const std::uint32_t* c) {
    float u;
    std::memcpy(&u, c + 2, sizeof u);
    return (c[0] | c[1] | c[2] | c[3]) == 0u ? std::nanf("") : u;
  };
  GridUpper upper;
  for (std::size_t i = 0; i < coarse; ++i) upper.coarse.push_back(bound(head.data() + 4 * (i + 1)));
  for (std::size_t i = 0; i < fine.size() / 4; ++i) {
    upper.fine.push_back(bound(fine.data() + 4 * i));
    upper.fine_far.push_back(fine[4 * i + 3] == 2u);
  }
  std::optional<ReposeCells> cells = repose_cells(parts_, next, upper);
  // A cell whose new list neither fits in its old one's room nor finds
  // room in the pool keeps its coarse cell's list, exact but longer: once
  // a hundredth of the cells more than after the last whole pass have, the
  // pool starts again from empty.
  if (cells && overflowed_ > overflowed_whole_ + static_cast<int>(cell_count(plan_) / 100)) cells.reset();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers_[0]);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n.nodes.size() * sizeof(std::uint32_t)), n.nodes.data());
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers_[1]);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n.floats.size() * sizeof(float)), n.floats.data());
  if (!cells) {
    const std::uint32_t zero = 0u;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers_[4]);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof zero, &zero);
  }
  bind();
  run_pass(*prune_, cells ? &*cells : nullptr);
  pruned_cells_ = cells ? cells->count() : cell_count(plan_);
  parts_ = next;
  from_cache_ = false;
  cache_note_.clear();
  measure();
  if (!cells) overflowed_whole_ = overflowed_;
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return true;
}

std::string GraphField::summary() const {
  if (!plan_.prune) return {};  // no grid (inline, too many nodes, or no finite box)
  const glm::ivec3 d = plan_.levels[0].dims;
  const std::string grid = "grid " + std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z) +
                           " and " + std::to_string(kGridLevels - 1) + " outer levels";
  if (plan_.keep_all)
    return grid + ", not pruned (--no-prune): every cell runs all " + std::to_string(program_) + " instructions";
  if (mean_list_ < 0.0) return {};
  char buf[256];
  std::snprintf(buf, sizeof buf, ", %s %.1f ms, mean list %.1f instructions (of %zu), %d cells kept their coarse list",
                from_cache_ ? "pruned grid read from the cache in" : "pruning", build_ms_, mean_list_, program_,
                overflowed_);
  std::string again;
  if (pruned_cells_ < cells())
    again = ", " + std::to_string(pruned_cells_) + " of " + std::to_string(cells()) + " cells pruned again";
  return grid + buf + again + cache_note_;
}

GraphField::~GraphField() { glDeleteBuffers(6, buffers_); }

void GraphField::bind() const {
  for (GLuint i = 0; i < 5; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3 + i, buffers_[i]);
}

}  // namespace ms
