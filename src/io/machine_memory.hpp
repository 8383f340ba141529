#pragma once
// The memory of the machine a scenario is read on, so that an input that would need more (a wall
// of 1e10 bricks) is refused with the figures before anything is allocated, instead of ending in
// std::bad_alloc or the kernel's out-of-memory killer.
#include <cstdint>
#include <string>

namespace blockdem {

/// [bytes] The machine's physical memory; 0 when the system does not say.
std::uint64_t physical_memory_bytes();

/// "1.7 GB", "23.4 GB", "20.0 TB": a byte count for messages (powers of 1000).
std::string format_bytes(double bytes);

}  // namespace blockdem
