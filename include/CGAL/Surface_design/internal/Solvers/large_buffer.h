// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Large arrays of plain numbers mapped from the kernel in transparent huge pages, where a first
// touch of 4 kB pages costs more than the work done on them.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LARGE_BUFFER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LARGE_BUFFER_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Surface_design {
namespace internal {

/// An array for large buffers (the supernodal factor's panels, the Lanczos basis). On Linux, from
/// 512 kB on, it is mapped directly from the kernel (pages that come zeroed, so a fresh buffer needs
/// no clearing pass), aligned to 2 MB and advised for transparent huge pages: a factor is written
/// once right after allocation, and with 4 kB pages the page faults of that first touch cost as
/// much as the factorization itself on the virtual machines we measured (7 to 13 us per fault: 35
/// ms for the 15 MB factor of a 30k-vertex mesh; 32 MB in 100 ms against 2 ms in huge pages on 1
/// Dec 2026). Elsewhere, and for small buffers, it comes from malloc.
template <class T>
class Large_buffer
{
  static_assert(std::is_trivially_copyable<T>::value, "plain numbers only");
  static constexpr std::size_t huge_page = std::size_t(1) << 21;
  static constexpr std::size_t mapped_from = std::size_t(1) << 19;

public:
  Large_buffer() = default;
  Large_buffer(const Large_buffer&) = delete;
  Large_buffer& operator=(const Large_buffer&) = delete;
  Large_buffer(Large_buffer&& other) noexcept { swap(other); }
  Large_buffer& operator=(Large_buffer&& other) noexcept
  {
    Large_buffer(std::move(other)).swap(*this);
    return *this;
  }
  ~Large_buffer() { release(); }

  /// Makes room for `n` values, all zero.
  void assign_zero(std::size_t n)
  {
    if(!resize_uninitialized(n))
      std::fill(m_data, m_data + n, T(0));
  }

  /// Makes room for `n` values (kept when the buffer already had room). Returns true when the
  /// values are known to be zero (fresh pages from the kernel).
  bool resize_uninitialized(std::size_t n)
  {
    if(n <= m_capacity)
    {
      m_size = n;
      return false;
    }
    release(); // on a failure below, the buffer is left empty
    m_size = 0;
    if(n > (SIZE_MAX - 2 * huge_page) / sizeof(T))
      throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__) && defined(MAP_ANONYMOUS)
    if(bytes >= mapped_from)
    {
      const std::size_t length = (bytes + 2 * huge_page - 1) / huge_page * huge_page; // room to align
      void* base = mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if(base == MAP_FAILED)
        throw std::bad_alloc();
      m_mapped = base;
      m_mapped_length = length;
      const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(base);
      const std::uintptr_t aligned = (address + huge_page - 1) / huge_page * huge_page;
      m_data = reinterpret_cast<T*>(aligned);
#if defined(MADV_HUGEPAGE)
      madvise(reinterpret_cast<void*>(aligned), length - (aligned - address), MADV_HUGEPAGE); // advice only
#endif
      m_capacity = (length - (aligned - address)) / sizeof(T);
      m_size = n;
      return true;
    }
#endif
    m_data = static_cast<T*>(std::malloc(bytes));
    if(m_data == nullptr)
      throw std::bad_alloc();
    m_capacity = n;
    m_size = n;
    return false;
  }

  T* data() { return m_data; }
  const T* data() const { return m_data; }
  std::size_t size() const { return m_size; }

private:
  void release() noexcept
  {
#if defined(__linux__) && defined(MAP_ANONYMOUS)
    if(m_mapped != nullptr)
      munmap(m_mapped, m_mapped_length);
    else
#endif
      std::free(m_data);
    m_data = nullptr;
    m_mapped = nullptr;
    m_capacity = m_mapped_length = 0;
  }

  void swap(Large_buffer& other) noexcept
  {
    std::swap(m_data, other.m_data);
    std::swap(m_size, other.m_size);
    std::swap(m_capacity, other.m_capacity);
    std::swap(m_mapped, other.m_mapped);
    std::swap(m_mapped_length, other.m_mapped_length);
  }

  T* m_data = nullptr;
  std::size_t m_size = 0, m_capacity = 0;
  void* m_mapped = nullptr; // the mapping holding m_data, if mapped
  std::size_t m_mapped_length = 0;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LARGE_BUFFER_H
