// Global operator new/delete for the fuzz targets, with a heap budget. MRPT 2.5 trusts the
// length fields of what it deserialises: a corrupt one asks for a 4 GiB string, or a
// CSensoryFrame of 4 billion observations (64 GiB of small blocks), before any read fails. In
// production that ends in std::bad_alloc or, on Linux with overcommit, in the OOM killer; the
// harness cannot tell these apart, so it gives every input a budget of 256 MiB of live heap (a
// 640x480 frame needs about 10 MiB), beyond which new throws std::bad_alloc as it does on a
// machine without the memory (ASan's own new would abort instead). The reader must then report
// the corrupt file, not crash.
// While an exception unwinds the stack the budget does not apply, and what is allocated then is
// not counted: destructors run then, and MRPT 2.5's ~CObservation3DRangeScan hands its buffers to
// its memory pool, allocating there as much as the corrupt entry's sizes say, and the pool keeps
// them (a throw from a destructor ends the program, whatever the reader does). Production
// allocates what the machine has at that point, as the harness then does; the count never goes
// below zero when such a block is freed.
#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <new>

namespace {
constexpr std::size_t kBudget = std::size_t{256} << 20;
std::atomic<std::size_t> g_live{0};

void* allocate(std::size_t n, std::size_t align) {
  n = n ? n : 1;
  const bool unwinding = std::uncaught_exceptions() > 0;
  if (!unwinding && (n > kBudget || g_live.load() > kBudget - n)) throw std::bad_alloc();
  void* p = align <= alignof(std::max_align_t)
                ? std::malloc(n)
                : std::aligned_alloc(align, (n + align - 1) / align * align);
  if (!p) throw std::bad_alloc();
  if (!unwinding) g_live += malloc_usable_size(p);
  return p;
}

void release(void* p) noexcept {
  if (!p) return;
  const std::size_t n = malloc_usable_size(p);
  std::size_t live = g_live.load();
  while (!g_live.compare_exchange_weak(live, live > n ? live - n : 0)) {
  }
  std::free(p);
}

void* allocateOrNull(std::size_t n) noexcept {
  try {
    return allocate(n, 0);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n, 0); }
void* operator new[](std::size_t n) { return allocate(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocateOrNull(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocateOrNull(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
