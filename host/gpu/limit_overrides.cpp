#include "gpu/limit_overrides.h"

namespace {

LimitOverrides overrides;

} // namespace

void setLimitOverrides(const LimitOverrides& lowered) {
    overrides = lowered;
}

const LimitOverrides& limitOverrides() {
    return overrides;
}
