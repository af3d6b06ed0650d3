#include "allocationcounter.h"

#include <atomic>
#include <cstdlib>
#include <malloc.h>
#include <new>

namespace {

std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};

void* counted(std::size_t size, std::size_t alignment)
{
    if (size == 0)
        size = 1;
    void* block = alignment <= alignof(std::max_align_t)
        ? std::malloc(size)
        : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    if (!block)
        return nullptr;
    const std::size_t usable = malloc_usable_size(block);
    const std::size_t now = g_live.fetch_add(usable, std::memory_order_relaxed) + usable;
    std::size_t seen = g_peak.load(std::memory_order_relaxed);
    while (now > seen && !g_peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
    }
    return block;
}

void release(void* block) noexcept
{
    if (!block)
        return;
    g_live.fetch_sub(malloc_usable_size(block), std::memory_order_relaxed);
    std::free(block);
}

void* countedOrThrow(std::size_t size, std::size_t alignment)
{
    if (void* block = counted(size, alignment))
        return block;
    throw std::bad_alloc();
}

} // namespace

namespace allocations {

std::size_t live()
{
    return g_live.load(std::memory_order_relaxed);
}

std::size_t peak()
{
    return g_peak.load(std::memory_order_relaxed);
}

void resetPeak()
{
    g_peak.store(g_live.load(std::memory_order_relaxed), std::memory_order_relaxed);
}

} // namespace allocations

void* operator new(std::size_t size)
{
    return countedOrThrow(size, 0);
}
void* operator new[](std::size_t size)
{
    return countedOrThrow(size, 0);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    return counted(size, 0);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
    return counted(size, 0);
}
void* operator new(std::size_t size, std::align_val_t alignment)
{
    return countedOrThrow(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment)
{
    return countedOrThrow(size, static_cast<std::size_t>(alignment));
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept
{
    return counted(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept
{
    return counted(size, static_cast<std::size_t>(alignment));
}
void operator delete(void* block) noexcept
{
    release(block);
}
void operator delete[](void* block) noexcept
{
    release(block);
}
void operator delete(void* block, std::size_t) noexcept
{
    release(block);
}
void operator delete[](void* block, std::size_t) noexcept
{
    release(block);
}
void operator delete(void* block, std::align_val_t) noexcept
{
    release(block);
}
void operator delete[](void* block, std::align_val_t) noexcept
{
    release(block);
}
void operator delete(void* block, std::size_t, std::align_val_t) noexcept
{
    release(block);
}
void operator delete[](void* block, std::size_t, std::align_val_t) noexcept
{
    release(block);
}
void operator delete(void* block, const std::nothrow_t&) noexcept
{
    release(block);
}
void operator delete[](void* block, const std::nothrow_t&) noexcept
{
    release(block);
}
void operator delete(void* block, std::align_val_t, const std::nothrow_t&) noexcept
{
    release(block);
}
void operator delete[](void* block, std::align_val_t, const std::nothrow_t&) noexcept
{
    release(block);
}
