// Frame memory estimate against the process's limit.
#include "app/memory_budget.h"

#include <algorithm>
#include <cstdint>
#include <sys/resource.h>
#include <sys/sysinfo.h>

namespace vista {

std::uint64_t estimatedFrameBytes(int width, int height) {
    return kFixedBytes + kBytesPerPixel * std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0));
}

std::uint64_t memoryLimitBytes() {
    std::uint64_t limit = UINT64_MAX;
    struct rlimit r {};
    if (::getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY) limit = std::uint64_t(r.rlim_cur);
    struct sysinfo info {};
    if (::sysinfo(&info) == 0) {
        const std::uint64_t total = (std::uint64_t(info.totalram) + std::uint64_t(info.totalswap)) * info.mem_unit;
        if (total > 0 && total < limit) limit = total;
    }
    return limit;
}

std::string checkFrameMemory(int width, int height) {
    const std::uint64_t need = estimatedFrameBytes(width, height), limit = memoryLimitBytes();
    if (need <= limit) return {};
    return "--size " + std::to_string(width) + "x" + std::to_string(height) + " needs about " +
           std::to_string(need >> 20) + " MiB, more than the " + std::to_string(limit >> 20) +
           " MiB this process may use (ulimit -v, memory and swap); choose a smaller --size";
}

}  // namespace vista
