// keepFreedMemory: tell the C library's allocator to keep memory a program frees instead of
// giving it back to the system at once. A search frees and makes the models of a generation
// (score/image/image_model.hpp: their coverage blocks and chromosome copies, a few KB each) every few
// milliseconds; returning the freed top of the heap and faulting it back in cost the tree scenes
// 2.9x the time of scoring a child from its parent (bench_incremental, tree-logo: 41 µs against
// 14 µs). What is kept is reused by the next generation; the peak is what the run needs anyway.
// Call once, at the start of a program (the CLI's main, the benchmarks); it changes no result.
#pragma once

namespace shapevo {

void keepFreedMemory();

}  // namespace shapevo
