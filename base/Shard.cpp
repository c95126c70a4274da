#include "base/Shard.hpp"

#include "base/Printable.hpp"

#include <charconv>

namespace speculum::base {

namespace {

bool parseWhole(std::string_view text, int& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}

} // namespace

Result<Shard> parseShard(const std::string& option, const std::string& text) {
    const std::size_t slash = text.find('/');
    Shard shard;
    if (slash == std::string::npos || !parseWhole(std::string_view(text).substr(0, slash), shard.index) ||
        !parseWhole(std::string_view(text).substr(slash + 1), shard.count))
        return Error{option + ": expected K/N such as 0/4 (the Kth of N shares, K from 0), got " +
                     quoted(text)};
    if (shard.count < 1 || shard.count > kMaxShards)
        return Error{option + ": " + quoted(text) + ": N is out of range (1.." + std::to_string(kMaxShards) +
                     ")"};
    if (shard.index < 0 || shard.index >= shard.count)
        return Error{option + ": " + quoted(text) + ": K is out of range (0.." +
                     std::to_string(shard.count - 1) + ", counted from 0)"};
    return shard;
}

std::vector<int> shardItems(const Shard& shard, int itemCount) {
    std::vector<int> items;
    if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count || itemCount <= 0)
        return items;
    if (!shard.contiguous) {
        for (int i = shard.index; i < itemCount; i += shard.count)
            items.push_back(i);
        return items;
    }
    // Runs as even as can be: shard k takes [k n / c, (k + 1) n / c), so the runs differ by one item at most.
    const long long n = itemCount, k = shard.index, c = shard.count;
    const long long begin = k * n / c, end = (k + 1) * n / c;
    for (long long i = begin; i < end; ++i)
        items.push_back(static_cast<int>(i));
    return items;
}

std::string shardText(const Shard& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count) +
           (shard.contiguous ? " contiguous" : "");
}

} // namespace speculum::base
