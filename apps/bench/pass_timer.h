// A Backend that forwards every call to another and, while timing is on, times each pass:
// it calls finish() at every pass boundary (the next beginPass, or the frame's finish), so
// a pass's time runs from its beginPass until all its work is done. `raster bench
// --passes` wraps both contenders in one to show which passes of a frame gain or lose
// against the GL driver. The extra finishes take away whatever overlap a driver finds
// between passes, so the passes add up to a little more than a raced frame.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "backends/backend.h"

namespace cli {

class PassTimer final : public scenes::Backend {
 public:
  struct Pass {
    std::string program;      // the first program drawn in it ("" for a pass that only clears)
    std::vector<double> ms;   // one time per timed frame
  };

  explicit PassTimer(scenes::Backend& inner) : inner_(inner) {}

  // Between setTiming(true) and setTiming(false), each frame's passes are timed; a frame
  // ends with finish().
  void setTiming(bool on) { timing_ = on; }
  const std::vector<Pass>& passes() const { return passes_; }

  std::string name() const override { return inner_.name(); }
  void resizeDefaultFramebuffer(int width, int height) override { inner_.resizeDefaultFramebuffer(width, height); }
  scenes::Handle createProgram(const std::string& program) override {
    const scenes::Handle handle = inner_.createProgram(program);
    programNames_[handle] = program;
    return handle;
  }
  scenes::Handle createMesh(const scenes::MeshData& mesh) override { return inner_.createMesh(mesh); }
  scenes::Handle createTexture(const scenes::TextureDesc& desc, const void* pixels = nullptr) override {
    return inner_.createTexture(desc, pixels);
  }
  scenes::Handle createFramebuffer(const scenes::FramebufferDesc& desc) override { return inner_.createFramebuffer(desc); }
  void beginPass(scenes::Handle framebuffer, const scenes::Viewport& viewport, const scenes::ClearOp& clear) override;
  void setUniform(scenes::Handle program, const std::string& name, const scenes::UniformValue& value) override {
    inner_.setUniform(program, name, value);
  }
  void bindTexture(int unit, scenes::Handle texture) override { inner_.bindTexture(unit, texture); }
  void draw(scenes::Handle program, scenes::Handle mesh, const scenes::DrawState& state, int instanceCount = 1) override;
  void finish() override;
  scenes::ImageData readColor(scenes::Handle framebuffer, int attachment = 0) override {
    return inner_.readColor(framebuffer, attachment);
  }
  scenes::ImageData readDepth(scenes::Handle framebuffer) override { return inner_.readDepth(framebuffer); }
  std::vector<std::pair<std::string, double>> statistics() const override { return inner_.statistics(); }
  void resetStatistics(bool timeStages = false) override { inner_.resetStatistics(timeStages); }

 private:
  void closePass();   // finishes the open pass and records its time

  scenes::Backend& inner_;
  bool timing_ = false;
  int open_ = -1;   // index of the pass in flight in this frame, -1 before the first
  std::chrono::steady_clock::time_point start_;
  std::vector<Pass> passes_;
  std::map<scenes::Handle, std::string> programNames_;
};

}  // namespace cli
