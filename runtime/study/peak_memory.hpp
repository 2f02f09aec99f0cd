// Peak resident memory of this process between two marks (Linux /proc; elsewhere unmeasured).
#pragma once

namespace pd {

// Resets the peak (VmHWM) to the current resident set; false when the kernel refuses.
bool reset_peak_memory();
// Peak resident set since the last reset, MiB; -1 when /proc/self/status is unreadable.
double peak_memory_mb();

}  // namespace pd
