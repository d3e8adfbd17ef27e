// How the program asks the C library to keep the memory of frame-sized buffers.
#pragma once

namespace rugosim::app {

// The encoder's pictures are megabytes each, and libx264 frees and allocates such buffers while
// it encodes (the renderer's own frames of 4 MB and more bypass malloc: huge_page_allocator.h).
// glibc serves blocks above its mmap threshold with a fresh mapping and hands them back to the
// kernel when freed; with transparent huge pages each new mapping is zeroed again, 2 MB at a time.
// Measured on 1080p clips (bench/render_bench.cpp), that costs 15–20% more CPU time, on some runs
// and not others. Raising the thresholds (32 MB, the largest mmap threshold glibc takes; 256 MB
// kept before trimming) keeps those blocks in the heap for reuse. Call once, before any thread
// starts; elsewhere than glibc it does nothing.
void keep_frame_memory();

}  // namespace rugosim::app
