// SPDX-License-Identifier: MIT
// THE list of contact laws, one line per law in its slot's list. To add a law: write
// src/model/contact/<slot>_<name>.hpp with a struct that has `slot`, `name`, `summary`, an inline
// `kernel` citing its equation, `fields` and a `configure` that checks parameters once (see
// tangential_linear_history.hpp); add it to its list below; add a test in tests/unit/model/ and a
// page in docs/models/. The force loop is compiled once per combination of the four lists
// (dispatch.hpp), so every kernel is inlined into it.
#pragma once
#include "model/contact/cohesion_constant_range.hpp"
#include "model/contact/cohesion_mfix_like.hpp"
#include "model/contact/cohesion_none.hpp"
#include "model/contact/cohesion_overlap_only.hpp"
#include "model/contact/normal_linear_spring_dashpot.hpp"
#include "model/contact/rolling_epsd.hpp"
#include "model/contact/rolling_mfix.hpp"
#include "model/contact/rolling_mfix21.hpp"
#include "model/contact/rolling_none.hpp"
#include "model/contact/tangential_linear_history.hpp"
#include "model/contact/tangential_none.hpp"

namespace silodem {

template <class... Laws>
struct LawList {};

using NormalLaws = LawList<NormalLinearSpringDashpot>;
using TangentialLaws = LawList<TangentialNone, TangentialLinearHistory>;
using RollingLaws = LawList<RollingNone, RollingMfix, RollingEpsd, RollingMfix21>;
using CohesionLaws =
    LawList<CohesionNone, CohesionOverlapOnly, CohesionConstantRange, CohesionMfixLike>;

}  // namespace silodem
