// SPDX-License-Identifier: MIT
// THE list of contact laws, one line per law in its slot's list. To add a law: write
// src/model/contact/<slot>_<name>.hpp with a struct that has `slot`, `name`, `summary`, its
// `Params`, its `history` (the values it keeps per contact: an array of the factor each takes
// when i and j swap), an inline `kernel` citing its equation (signatures: slots.hpp), `fields`
// and a `configure` that checks the parameters once and returns the Params (see
// tangential_linear_history.hpp); add it to its list below; add a test in tests/unit/model/ and a
// page in docs/models/. The force loop is compiled once per combination of the four lists
// (dispatch.hpp), so every kernel is inlined into it.
#pragma once
#include <variant>

#include "model/contact/cohesion_constant_range.hpp"
#include "model/contact/cohesion_mfix_like.hpp"
#include "model/contact/cohesion_none.hpp"
#include "model/contact/cohesion_overlap_only.hpp"
#include "model/contact/normal_hertz.hpp"
#include "model/contact/normal_linear_spring_dashpot.hpp"
#include "model/contact/normal_luding.hpp"
#include "model/contact/rolling_epsd.hpp"
#include "model/contact/rolling_mfix.hpp"
#include "model/contact/rolling_mfix21.hpp"
#include "model/contact/rolling_none.hpp"
#include "model/contact/tangential_linear_history.hpp"
#include "model/contact/tangential_none.hpp"

namespace silodem {

template <class... Laws>
struct LawList {};

using NormalLaws = LawList<NormalLinearSpringDashpot, NormalHertz, NormalLuding>;
using TangentialLaws = LawList<TangentialNone, TangentialLinearHistory>;
using RollingLaws = LawList<RollingNone, RollingMfix, RollingEpsd, RollingMfix21>;
using CohesionLaws =
    LawList<CohesionNone, CohesionOverlapOnly, CohesionConstantRange, CohesionMfixLike>;

// The Params of whichever law of a list is chosen (by its position in the list).
template <class List>
struct ParamsOfList;
template <class... Laws>
struct ParamsOfList<LawList<Laws...>> {
  using type = std::variant<typename Laws::Params...>;
};
template <class List>
using SlotParams = typename ParamsOfList<List>::type;

// Position of Law in List.
template <class Law, class List>
struct IndexInList;
template <class Law, class... Laws>
struct IndexInList<Law, LawList<Law, Laws...>> {
  static constexpr std::size_t value = 0;
};
template <class Law, class First, class... Laws>
struct IndexInList<Law, LawList<First, Laws...>> {
  static constexpr std::size_t value = 1 + IndexInList<Law, LawList<Laws...>>::value;
};

template <class Law>
inline constexpr int history_size = int(Law::history.size());

}  // namespace silodem
