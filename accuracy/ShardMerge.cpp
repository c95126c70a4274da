#include "accuracy/ShardMerge.hpp"

#include "base/Printable.hpp"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <set>

namespace speculum::accuracy {

namespace fs = std::filesystem;

namespace {

std::string named(const fs::path& folder) {
    return base::printable(folder.string());
}

// "1/4": the shard as RanOn and the messages name it (its kind is the same in every folder of a merge).
std::string shardName(const base::Shard& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

std::string sizeText(const RunInfo& run) {
    return std::to_string(run.width) + "x" + std::to_string(run.height);
}

// Why shard `b` cannot join shard `a`'s run, or nothing when it can.
std::optional<std::string> mismatch(const ShardFolder& a, const ShardFolder& b) {
    const ShardInfo &sa = *a.run.shard, &sb = *b.run.shard;
    const std::string against = named(b.folder) + ": ";
    if (sa.shard.count != sb.shard.count)
        return against + "shard " + shardName(sb.shard) + ", but " + named(a.folder) + " is shard " +
               shardName(sa.shard) + ": the shards of one run share their count";
    if (sa.shard.contiguous != sb.shard.contiguous)
        return against + (sb.shard.contiguous ? "a contiguous shard" : "an interleaved shard") + ", but " +
               named(a.folder) + " is " + (sa.shard.contiguous ? "contiguous" : "interleaved") +
               ": the shards of one run share --contiguous";
    const std::string other = against + "measured another run than " + named(a.folder) + " (";
    if (a.run.width != b.run.width || a.run.height != b.run.height)
        return other + "size " + sizeText(b.run) + " against " + sizeText(a.run) + ")";
    if (a.run.quick != b.run.quick)
        return other + (b.run.quick ? "quick against full" : "full against quick") + ")";
    if (sa.projectDigest != sb.projectDigest)
        return other + "another project file: their contents differ)";
    if (sa.convergence != sb.convergence)
        return other + (sb.convergence ? "with" : "without") + " --convergence against " +
               (sa.convergence ? "with" : "without") + ")";
    if (sa.configurations != sb.configurations)
        return other + "another list of configurations: " + std::to_string(sb.configurations.size()) +
               " against " + std::to_string(sa.configurations.size()) + ")";
    return std::nullopt;
}

base::Result<QJsonObject> readRoot(const fs::path& folder) {
    const fs::path path = folder / "results.json";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return base::Error{named(folder) + ": not a folder"};
    if (!fs::exists(path, ec))
        return base::Error{named(folder) + ": not the output of a bench shard (no results.json)"};
    QFile file(QString::fromStdString(path.string()));
    if (!file.open(QIODevice::ReadOnly))
        return base::Error{named(path) + ": cannot read (" + file.errorString().toStdString() + ")"};
    QJsonParseError error;
    const QJsonDocument json = QJsonDocument::fromJson(file.readAll(), &error);
    if (json.isNull() || !json.isObject())
        return base::Error{named(path) + ": not JSON (" + error.errorString().toStdString() + ")"};
    return json.object();
}

// The records must be the shard's share, in its order: anything else is not what `bench --shard` wrote.
base::Status checkShare(const ShardFolder& shard) {
    const ShardInfo& info = *shard.run.shard;
    const int count = static_cast<int>(info.configurations.size());
    std::set<std::string> share;
    for (int i : base::shardItems(info.shard, count))
        share.insert(info.configurations[static_cast<std::size_t>(i)]);
    for (const Record& r : shard.records)
        if (!share.count(r.config.id))
            return base::Error{named(shard.folder) + ": holds configuration " + base::quoted(r.config.id) +
                               ", which is not in shard " + shardName(info.shard) + "'s share"};
    return base::Done{};
}

} // namespace

base::Result<ShardFolder> readShardFolder(const fs::path& folder) {
    auto root = readRoot(folder);
    if (!root)
        return base::Error{root.error()};
    const std::string name = (folder / "results.json").string();
    if (root->value("format").toString() != QStringLiteral("speculum-bench"))
        return base::Error{base::printable(name) + ": not a speculum bench result"};
    if (!root->value("shard").isObject())
        return base::Error{named(folder) +
                           ": the output of a whole bench run, not of a shard (bench --shard K/N)"};
    ShardFolder shard;
    shard.folder = folder;
    if (root->value("results").toArray().isEmpty()) {
        shard.run = runInfoFromJson(*root); // a share with no configuration: more shards than configurations
    } else {
        auto read = readJson(*root, base::printable(name));
        if (!read)
            return base::Error{read.error()};
        if (read->unknownFamilies > 0)
            return base::Error{base::printable(name) + ": holds families this version does not know"};
        shard.run = std::move(read->run);
        shard.records = std::move(read->records);
    }
    const ShardInfo& info = *shard.run.shard;
    if (info.shard.count < 1 || info.shard.index < 0 || info.shard.index >= info.shard.count)
        return base::Error{base::printable(name) + ": shard: not K/N with 0 <= K < N"};
    if (base::Status share = checkShare(shard); !share)
        return base::Error{share.error()};
    return shard;
}

namespace {

// The shard that measures configuration `i` of `count`.
base::Shard shardOf(const base::Shard& kind, int i, int count) {
    for (int k = 0; k < kind.count; ++k) {
        const base::Shard shard{k, kind.count, kind.contiguous};
        const std::vector<int> items = base::shardItems(shard, count);
        if (std::binary_search(items.begin(), items.end(), i))
            return shard;
    }
    return kind;
}

// Which folder holds each configuration, refusing one held twice or by none.
base::Result<std::vector<std::size_t>> holders(const std::vector<ShardFolder>& shards) {
    const ShardInfo& first = *shards.front().run.shard;
    std::map<std::string, std::size_t> holder;
    for (std::size_t s = 0; s < shards.size(); ++s)
        for (const Record& r : shards[s].records)
            if (auto [at, fresh] = holder.emplace(r.config.id, s); !fresh)
                return base::Error{"configuration " + base::quoted(r.config.id) + " is in both " +
                                   named(shards[at->second].folder) + " and " + named(shards[s].folder) +
                                   " (shard " + shardName(shards[s].run.shard->shard) + " each)"};
    std::vector<std::size_t> out;
    const int count = static_cast<int>(first.configurations.size());
    for (int i = 0; i < count; ++i) {
        const std::string& id = first.configurations[static_cast<std::size_t>(i)];
        const auto at = holder.find(id);
        if (at == holder.end())
            return base::Error{"configuration " + base::quoted(id) + " is in none of the folders: shard " +
                               shardName(shardOf(first.shard, i, count)) + " measures it"};
        out.push_back(at->second);
    }
    return out;
}

// The run's description from its shards: the first one's, with what each shard alone measured (the
// references in first-use order, the furnace, the convergence study) and where each shard ran.
RunInfo mergedRun(const std::vector<ShardFolder>& shards, const std::vector<Record>& records,
                  const std::vector<std::size_t>& holder,
                  std::map<ReferenceKind, fs::path>& referenceFolder) {
    RunInfo run = shards.front().run;
    run.shard.reset();
    run.references.clear();
    run.furnace.clear();
    run.convergence.reset();
    for (std::size_t i = 0; i < records.size(); ++i) {
        const ReferenceKind kind = records[i].config.reference;
        if (referenceFolder.count(kind))
            continue;
        for (const ReferenceInfo& ref : shards[holder[i]].run.references)
            if (ref.kind == kind) {
                run.references.push_back(ref);
                referenceFolder[kind] = shards[holder[i]].folder;
            }
    }
    std::vector<std::string> renderers;
    for (const ShardFolder& s : shards) {
        if (!s.run.furnace.empty())
            run.furnace = s.run.furnace;
        if (s.run.convergence)
            run.convergence = s.run.convergence;
        run.shards.push_back(
            {shardName(s.run.shard->shard), s.run.shard->host, s.run.renderer, s.records.size()});
        if (std::find(renderers.begin(), renderers.end(), s.run.renderer) == renderers.end())
            renderers.push_back(s.run.renderer);
    }
    run.renderer.clear();
    for (const std::string& r : renderers)
        run.renderer += (run.renderer.empty() ? "" : " and ") + r;
    return run;
}

} // namespace

base::Result<MergedShards> mergeShards(const std::vector<fs::path>& folders) {
    if (folders.empty())
        return base::Error{"--merge: no folder to merge"};
    std::vector<ShardFolder> shards;
    for (const fs::path& folder : folders) {
        for (const ShardFolder& earlier : shards) {
            std::error_code ec;
            if (fs::equivalent(earlier.folder, folder, ec))
                return base::Error{"--merge: " + named(folder) + " is given twice"};
        }
        auto shard = readShardFolder(folder);
        if (!shard)
            return base::Error{shard.error()};
        if (!shards.empty())
            if (std::optional<std::string> why = mismatch(shards.front(), *shard))
                return base::Error{*why};
        shards.push_back(std::move(*shard));
    }
    std::sort(shards.begin(), shards.end(), [](const ShardFolder& a, const ShardFolder& b) {
        return a.run.shard->shard.index < b.run.shard->shard.index;
    });
    auto holder = holders(shards);
    if (!holder)
        return base::Error{holder.error()};
    MergedShards merged;
    merged.projectDigest = shards.front().run.shard->projectDigest;
    for (std::size_t i = 0; i < holder->size(); ++i) {
        const ShardFolder& shard = shards[(*holder)[i]];
        const std::string& id = shard.run.shard->configurations[i];
        Record record = *std::find_if(shard.records.begin(), shard.records.end(),
                                      [&](const Record& r) { return r.config.id == id; });
        record.ranOn = RanOn{shardName(shard.run.shard->shard), shard.run.shard->host};
        merged.records.push_back(std::move(record));
        merged.recordFolder.push_back(shard.folder);
    }
    merged.run = mergedRun(shards, merged.records, *holder, merged.referenceFolder);
    return merged;
}

} // namespace speculum::accuracy
