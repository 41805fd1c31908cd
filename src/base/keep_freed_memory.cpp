// keepFreedMemory with glibc's mallopt; elsewhere it does nothing.
#include "base/keep_freed_memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace shapevo {

void keepFreedMemory() {
#if defined(__GLIBC__)
    mallopt(M_TRIM_THRESHOLD, 1 << 30);  // give back only a freed top of the heap above 1 GiB
    mallopt(M_TOP_PAD, 64 << 20);         // and grow the heap 64 MiB at a time
#endif
}

}  // namespace shapevo
