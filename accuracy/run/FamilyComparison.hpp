#pragma once

#include "accuracy/Results.hpp"
#include "accuracy/run/Measure.hpp"
#include "base/Result.hpp"

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

namespace speculum::accuracy {

// The records of each family, by index into the run's records, in the families' order and each family's
// records in the run's order.
std::map<Family, std::vector<std::size_t>> familyMembers(const std::vector<Record>& records);

// The figures that compare a record with the others of its family rather than with its reference:
// Record::tiedWith (the pairs the reference's noise cannot tell apart, on the pixels the family is judged
// by) and Record::flipToBest (how far a viewer could tell its image from the family's best one). `members`
// are one family's records (familyMembers), `image(i)` record i's frame, linear. A run on one machine
// calls it with the frames it holds, a merge of shards with the frames the shards kept; both give the
// same figures, in the same order, for the same frames.
base::Status compareFamily(std::vector<Record>& records, const std::vector<std::size_t>& members,
                           const std::function<const render::Image&(std::size_t)>& image,
                           const std::map<ReferenceKind, Reference>& references);

} // namespace speculum::accuracy
