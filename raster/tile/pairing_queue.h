// The pairing state machine GroupShader<Float8> (group_shader_avx2.h) and
// CoarseShader<Float8> (coarse_shader_avx2.h) share: a group of a paired draw waits in its
// slot until the next ready group joins it (one Float8x2 call for both), or until one that
// cannot join, or the end of the tile, sends it alone. Groups are handed over in the order
// they became ready, and each passed its depth test before that, so the framebuffer ends as
// if each were shaded alone.
//
// Policy says what a slot is and how it is shaded:
//   bool paired(const Slot&)                  its draw's groups are shaded two per call
//   bool canPair(const Slot& a, const Slot& b)
//   void shadeOne(Slot&), void shadePair(Slot& a, Slot& b)   (a's colours land first)
#pragma once

namespace raster {

template <class Slot, class Policy>
class PairingQueue {
 public:
  explicit PairingQueue(Policy policy) : policy_(policy) {}
  // Where the next group is prepared: never the waiting group's slot.
  Slot& next() { return slots_[nextIndex()]; }
  // The group prepared in next() is ready.
  void push() {
    const int index = nextIndex();
    Slot& ready = slots_[index];
    if (policy_.paired(ready)) {
      if (waiting_ >= 0 && policy_.canPair(slots_[waiting_], ready)) {
        policy_.shadePair(slots_[waiting_], ready);
        waiting_ = -1;
        return;
      }
      flush();
      waiting_ = index;
      return;
    }
    flush();
    policy_.shadeOne(ready);
  }
  // Shades the waiting group alone.
  void flush() {
    if (waiting_ >= 0) policy_.shadeOne(slots_[waiting_]);
    waiting_ = -1;
  }

 private:
  int nextIndex() const { return waiting_ == 0 ? 1 : 0; }
  Policy policy_;
  Slot slots_[2];
  int waiting_ = -1;   // the slot of the group waiting for a partner, or -1
};

}  // namespace raster
