#include "accuracy/run/FamilyComparison.hpp"

#include "accuracy/Analysis.hpp"

namespace speculum::accuracy {

namespace {

// The metric the family is judged by, from all of its records (as the report ranks them).
Metric familyMetric(const std::vector<Record>& records, const std::vector<std::size_t>& members) {
    std::vector<const Record*> rows;
    for (std::size_t i : members)
        rows.push_back(&records[i]);
    return judgedMetric(records[members.front()].config.family, rows);
}

// Every pair of the family that shares a reference, in the order the pairs (a < b) come: each record's
// tiedWith lists its ties in the order of the run's records.
base::Status findTies(std::vector<Record>& records, const std::vector<std::size_t>& members,
                      const std::function<const render::Image&(std::size_t)>& image,
                      const std::map<ReferenceKind, Reference>& references, Metric metric) {
    for (std::size_t x = 0; x < members.size(); ++x)
        for (std::size_t y = x + 1; y < members.size(); ++y) {
            Record &ra = records[members[x]], &rb = records[members[y]];
            if (ra.config.reference != rb.config.reference)
                continue;
            auto tie = comparedWithinNoise(image(members[x]), image(members[y]),
                                           references.at(ra.config.reference), metric);
            if (!tie)
                return base::Error{tie.error()};
            if (*tie) {
                ra.tiedWith.push_back(rb.config.id);
                rb.tiedWith.push_back(ra.config.id);
            }
        }
    return base::Done{};
}

// Each record's distance to the family's best (by mean FLIP on the family's pixels). The glossy family
// has a best per roughness, and the scene's is one record: both are left out.
base::Status compareWithBest(std::vector<Record>& records, const std::vector<std::size_t>& members,
                             const std::function<const render::Image&(std::size_t)>& image,
                             const std::map<ReferenceKind, Reference>& references, Metric metric) {
    const Family family = records[members.front()].config.family;
    if (family == Family::Glossy || family == Family::Scene)
        return base::Done{};
    std::size_t best = members.front();
    for (std::size_t i : members)
        if (*focusFlip(records[i], metric) < *focusFlip(records[best], metric))
            best = i;
    for (std::size_t i : members) {
        auto apart = flipBetween(image(i), image(best), references.at(records[i].config.reference), metric);
        if (!apart)
            return base::Error{apart.error()};
        records[i].flipToBest = *apart;
    }
    return base::Done{};
}

} // namespace

std::map<Family, std::vector<std::size_t>> familyMembers(const std::vector<Record>& records) {
    std::map<Family, std::vector<std::size_t>> families;
    for (std::size_t i = 0; i < records.size(); ++i)
        families[records[i].config.family].push_back(i);
    return families;
}

base::Status compareFamily(std::vector<Record>& records, const std::vector<std::size_t>& members,
                           const std::function<const render::Image&(std::size_t)>& image,
                           const std::map<ReferenceKind, Reference>& references) {
    if (members.empty())
        return base::Done{};
    const Metric metric = familyMetric(records, members);
    if (base::Status tied = findTies(records, members, image, references, metric); !tied)
        return tied;
    return compareWithBest(records, members, image, references, metric);
}

} // namespace speculum::accuracy
