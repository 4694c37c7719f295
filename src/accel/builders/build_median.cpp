#include "accel/builders/build_median.h"

#include "accel/builders/top_down_builder.h"

namespace glint::accel {
namespace {

std::optional<detail::Split> median_policy(const detail::SplitContext& context, const detail::PrimRange& range) {
  if (range.size() <= context.options.max_leaf_size) return std::nullopt;
  return detail::object_median_split(context, range);
}

}  // namespace

Bvh build_median(const BuildInput& input, const BuildOptions& options) {
  return detail::build_top_down(input, options, "median", median_policy);
}

}  // namespace glint::accel
