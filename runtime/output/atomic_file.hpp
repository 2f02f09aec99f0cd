// Whole-file writes that never leave a truncated result: write a temporary, then rename.
#pragma once

#include <string>
#include <string_view>

namespace pd {

// Creates missing parent directories, writes content to path + ".RUNID.N.tmp" (unique:
// run_id() and a per-process count), flushes, and
// renames it over path (atomic on POSIX within one filesystem). On any failure the
// temporary is removed and std::runtime_error names the path.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace pd
