#pragma once

// Linking two elements of a nested GRAFCET by naming them in order, as a
// mouse drag from one to the other does in web GRAFCET editors. The meaning
// follows the direction of the link, as IEC 60848 reads a GRAFCET top to
// bottom:
//  - step S onto transition T: T now follows S (S joins T's upstream set; a
//    second upstream step makes T a synchronisation);
//  - transition T onto step S: S now follows T (S joins T's downstream set;
//    a second downstream step makes T a simultaneous divergence);
//  - step A onto step B: a new transition A → B with the receptivity TRUE,
//    drawn as a loop line or a jump arrow (addJump);
//  - transition onto transition: refused, steps and transitions alternate.
// A link that exists already and a step linked to itself through one
// transition are refused too. Every refusal is a failed Status whose code
// (kLink...) the editor words for the user.

#include "core/model/grafcet.h"
#include "core/model/grafcetediting.h"
#include "core/model/status.h"

#include <string_view>

namespace core {

inline constexpr std::string_view kLinkTransitionToTransition = "link-transition-to-transition";
inline constexpr std::string_view kLinkExists = "link-exists";
inline constexpr std::string_view kLinkStepToItself = "link-step-to-itself";
inline constexpr std::string_view kLinkUnknownElement = "link-unknown-element";

// One end of a link: a step or a transition, by number.
struct GrafcetLinkEnd {
    enum class Kind { Step, Transition };
    Kind kind = Kind::Step;
    int number = 0;

    static GrafcetLinkEnd step(int number) { return {Kind::Step, number}; }
    static GrafcetLinkEnd transition(int number) { return {Kind::Transition, number}; }
    bool isStep() const { return kind == Kind::Step; }
    bool operator==(const GrafcetLinkEnd&) const = default;
};

// Success when link() would make the link; otherwise why not (the GRAFCET
// is not touched).
Status checkLink(const Grafcet& grafcet, GrafcetLinkEnd from, GrafcetLinkEnd to);
// Makes the link or refuses it as checkLink() does. A step-to-step link
// reports its new transition through `created` (may be null).
Status link(Grafcet& grafcet, GrafcetLinkEnd from, GrafcetLinkEnd to, GrafcetCreated* created = nullptr);

} // namespace core
