// Scratch arrays reused from step to step: the per-particle accumulators of the sweeps and the
// buffers that re-ordering gathers into. Buffers are kept by element type and slot, so a run
// allocates them in its first step and never again (no allocation per step), and the
// re-ordering buffers double as accumulators (they are idle during the sweeps).
#pragma once

#include <cstddef>
#include <memory>
#include <typeindex>
#include <utility>
#include <vector>

namespace flume {

class SweepWorkspace {
 public:
  // The buffer `slot` of element type T, resized to n (contents unspecified).
  template <class T>
  std::vector<T>& buffer(std::size_t slot, std::size_t n) {
    auto& v = holder<T>(slot).data;
    v.resize(n);
    return v;
  }

  std::size_t bytes() const {
    std::size_t b = 0;
    for (const auto& [type, h] : holders_)
      b += h->bytes();
    return b;
  }

 private:
  struct HolderBase {
    virtual ~HolderBase() = default;
    virtual std::size_t bytes() const = 0;
  };
  template <class T>
  struct Holder final : HolderBase {
    std::vector<T> data;
    std::size_t bytes() const override { return data.capacity() * sizeof(T); }
  };

  template <class T>
  Holder<T>& holder(std::size_t slot) {
    const std::type_index type(typeid(T));
    std::size_t seen = 0;
    for (auto& [t, h] : holders_)
      if (t == type && seen++ == slot) return static_cast<Holder<T>&>(*h);
    while (seen++ <= slot)
      holders_.emplace_back(type, std::make_unique<Holder<T>>());
    return static_cast<Holder<T>&>(*holders_.back().second);
  }

  std::vector<std::pair<std::type_index, std::unique_ptr<HolderBase>>> holders_;
};

}  // namespace flume
