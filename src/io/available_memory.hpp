#pragma once
// Memory the process may still allocate: the smallest of /proc/meminfo MemAvailable, the headroom
// under the address-space limit (ulimit -v) and under the cgroup limit (memory.max). Infinity
// when none is known. Used to refuse work, or a read, that cannot fit before it starts.
namespace rollspec::io {

double available_memory();

}  // namespace rollspec::io
