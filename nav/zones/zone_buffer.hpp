// Uninitialised scratch arrays for the zone stages (private to the zones room).
#pragma once

// Scratch arrays for the zone stages (private), taken from the caller's memory resource and
// left uninitialised: each stage writes every element before it reads it, and filling a whole
// image-sized array first costs about as much as the pass that then overwrites it.

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <type_traits>
#include <utility>

namespace marsokhod::nav::detail {

/// A fixed-size array of trivial elements whose values start indeterminate.
template <class T>
class ScratchBuffer {
  static_assert(std::is_trivially_default_constructible_v<T> &&
                std::is_trivially_destructible_v<T>);

public:
  explicit ScratchBuffer(std::pmr::memory_resource* memory) : memory_(memory) {}
  ScratchBuffer(std::size_t size, std::pmr::memory_resource* memory)
      : memory_(memory), size_(size) {
    if (size_ == 0)
      return;
    data_ = static_cast<T*>(memory_->allocate(size_ * sizeof(T), alignof(T)));
    std::uninitialized_default_construct_n(data_, size_);
  }
  ScratchBuffer(ScratchBuffer&& other) noexcept
      : memory_(other.memory_), data_(std::exchange(other.data_, nullptr)),
        size_(std::exchange(other.size_, 0)) {}
  ScratchBuffer& operator=(ScratchBuffer&& other) noexcept {
    std::swap(memory_, other.memory_);
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    return *this;
  }
  ScratchBuffer(const ScratchBuffer&) = delete;
  ScratchBuffer& operator=(const ScratchBuffer&) = delete;
  ~ScratchBuffer() {
    if (data_ != nullptr)
      memory_->deallocate(data_, size_ * sizeof(T), alignof(T));
  }

  std::size_t size() const { return size_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

private:
  std::pmr::memory_resource* memory_;
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

} // namespace marsokhod::nav::detail
