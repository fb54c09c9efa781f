#pragma once
// The memory a benchmark reports: the process's peak, and (on Linux) the peak of one step.
namespace maxillo::bench {

// Peak resident memory of this process so far, kB (getrusage).
long peak_memory_kb();

// Resets the kernel's high-water mark of this process's resident memory to what it holds now
// ("5" written to /proc/self/clear_refs), so that resident_peak_kb() then measures one step.
// False where that cannot be done.
bool reset_resident_peak();
long resident_peak_kb();  // VmHWM of /proc/self/status, kB; 0 if unreadable

}  // namespace maxillo::bench
