// Per-pass timing of a wrapped backend (pass_timer.h).
#include "apps/bench/pass_timer.h"

namespace cli {

void PassTimer::closePass() {
  if (!timing_ || open_ < 0) return;
  inner_.finish();
  passes_[size_t(open_)].ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count());
}

void PassTimer::beginPass(scenes::Handle framebuffer, const scenes::Viewport& viewport, const scenes::ClearOp& clear) {
  if (timing_) {
    closePass();
    ++open_;
    if (size_t(open_) == passes_.size()) passes_.emplace_back();
    start_ = std::chrono::steady_clock::now();
  }
  inner_.beginPass(framebuffer, viewport, clear);
}

void PassTimer::draw(scenes::Handle program, scenes::Handle mesh, const scenes::DrawState& state, int instanceCount) {
  if (timing_ && open_ >= 0 && passes_[size_t(open_)].program.empty()) {
    const auto name = programNames_.find(program);
    passes_[size_t(open_)].program = name != programNames_.end() ? name->second : "program " + std::to_string(program);
  }
  inner_.draw(program, mesh, state, instanceCount);
}

void PassTimer::finish() {
  if (timing_ && open_ >= 0) {
    closePass();   // finishes the inner backend too
    open_ = -1;
    return;
  }
  inner_.finish();
}

}  // namespace cli
