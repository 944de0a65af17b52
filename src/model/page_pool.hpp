// Storage that the threads of the model's update fill in pages, kept from
// one update to the next (issue 20, steady-state memory). The update writes
// an unknown number of results of unknown sizes from several threads;
// blocks allocated at their exact size, per chunk of the evaluation, left
// the allocator with holes of every size, and a steady-state update kept
// growing the resident memory by a third over what it held (measured on
// the bundle of model_scaling: doc/guide-model.md, "Scaling"). Pages of one
// size are reused as they are: an update that needs no more than the last
// one allocates nothing.
//
// A pool hands out whole pages (acquire, under a lock: one in several
// hundred requests); each thread cuts its requests from its current page
// (PageCursor). The address of an element never changes until the pool is
// rewound, so the update keeps pointers into it.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace b2b {
namespace model {

template <class T>
class PagePool {
 public:
  // Elements of a page: 32 kB, which holds every request of the update (the
  // largest, a line pair's record with 32 points, is 400 doubles); a larger
  // request gets a page of its own size.
  static constexpr size_t kPage = (size_t(32) << 10) / sizeof(T);
  struct Page {
    T* data;
    size_t size;
  };

  PagePool() = default;
  PagePool(const PagePool&) = delete;
  PagePool& operator=(const PagePool&) = delete;

  // Every page free again (what they held is dead); the memory stays.
  void rewind() { used_ = 0; }
  // A free page of at least n elements, from any thread; allocates one when
  // none is free (std::bad_alloc leaves the pool as it was).
  Page acquire(size_t n) {
    std::lock_guard<std::mutex> hold(lock_);
    const size_t want = n > kPage ? n : kPage;
    if (used_ == pages_.size()) {
      pages_.emplace_back();  // the slot first: then nothing throws after the allocation
      try {
        pages_.back() = Owned{std::unique_ptr<T[]>(new T[want]), want};
      } catch (...) {
        pages_.pop_back();
        throw;
      }
    } else if (pages_[used_].size < want) {
      pages_[used_] = Owned{std::unique_ptr<T[]>(new T[want]), want};
    }
    Owned& p = pages_[used_++];
    return Page{p.data.get(), p.size};
  }
  // Frees the pages not handed out since the last rewind: the pool holds
  // what the last update used, not the most any update ever did.
  void release_unused() { pages_.resize(used_); }
  void swap(PagePool& o) noexcept {
    pages_.swap(o.pages_);
    std::swap(used_, o.used_);
  }
  void clear() {
    pages_.clear();
    pages_.shrink_to_fit();
    used_ = 0;
  }

 private:
  struct Owned {
    std::unique_ptr<T[]> data;
    size_t size = 0;
  };
  std::mutex lock_;
  std::vector<Owned> pages_;
  size_t used_ = 0;  // pages_[0, used_) handed out since the last rewind
};

// One thread's current page of a pool: requests are cut from it in order.
template <class T>
class PageCursor {
 public:
  explicit PageCursor(PagePool<T>& pool) : pool_(&pool) {}
  // n contiguous elements (their values are whatever the page held).
  T* take(size_t n) {
    if (n > left_) {
      const typename PagePool<T>::Page p = pool_->acquire(n);
      at_ = p.data;
      left_ = p.size;
    }
    T* r = at_;
    at_ += n;
    left_ -= n;
    return r;
  }
  // Gives the last n elements of the last take() back to the page.
  void give_back(size_t n) {
    at_ -= n;
    left_ += n;
  }

 private:
  PagePool<T>* pool_;
  T* at_ = nullptr;
  size_t left_ = 0;
};

}  // namespace model
}  // namespace b2b
