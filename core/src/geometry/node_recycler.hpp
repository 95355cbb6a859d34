#pragma once
// A memory resource for one node-based container (the sweep's std::pmr::set): blocks of the
// size freed first are kept on a free list and handed out again; fresh blocks come from a
// monotonic arena released with the resource. The sweep's status stays small while n nodes
// enter and leave it, so a handful of blocks serve them all, and each allocation is a pointer
// pop (std::pmr::unsynchronized_pool_resource's size-class bookkeeping was 2% of the fast
// engine's decision on KAZ). Not thread-safe: one container, one thread. Internal to core.
#include <algorithm>
#include <cstddef>
#include <memory_resource>
#include <new>

namespace penshape::detail {

class NodeRecycler : public std::pmr::memory_resource {
 public:
  NodeRecycler() = default;
  NodeRecycler(const NodeRecycler&) = delete;
  NodeRecycler& operator=(const NodeRecycler&) = delete;
  ~NodeRecycler() override = default;

 private:
  struct FreeBlock {
    FreeBlock* next;
  };

  void* do_allocate(std::size_t bytes, std::size_t align) override {
    if (free_ != nullptr && bytes == size_ && align == align_) {
      FreeBlock* block = free_;
      free_ = block->next;
      return block;
    }
    // Every block can hold a free-list link, so any block of the recycled size can be reused.
    return arena_.allocate(std::max(bytes, sizeof(FreeBlock)), std::max(align, alignof(FreeBlock)));
  }

  void do_deallocate(void* p, std::size_t bytes, std::size_t align) override {
    if (size_ == 0) {
      size_ = bytes;
      align_ = align;
    }
    // Blocks of another size stay in the arena until the resource goes.
    if (bytes != size_ || align != align_) return;
    free_ = ::new (p) FreeBlock{free_};
  }

  [[nodiscard]] bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }

  std::pmr::monotonic_buffer_resource arena_;
  FreeBlock* free_ = nullptr;
  std::size_t size_ = 0;
  std::size_t align_ = 0;
};

} // namespace penshape::detail
