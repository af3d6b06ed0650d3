#include "core/layout/grafcetlayout.h"

#include "core/layout/grafcetactiontext.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace core {

const GrafcetStepLayout* GrafcetLayout::step(int number) const
{
    for (const GrafcetStepLayout& candidate : steps) {
        if (candidate.number == number)
            return &candidate;
    }
    return nullptr;
}

const GrafcetTransitionLayout* GrafcetLayout::transition(int number) const
{
    for (const GrafcetTransitionLayout& candidate : transitions) {
        if (candidate.number == number)
            return &candidate;
    }
    return nullptr;
}

namespace {

// Vertical room of the pieces of a column (see docs/grafcet-layout.md).
constexpr double kStepTopGap = 20;       // link into a step box; a loop arrives halfway
constexpr double kTransitionHeight = 40; // link, bar in the middle, link
constexpr double kLabelGap = 6;          // between a bar's end and its label
constexpr double kLineMargin = 10;       // between a branch line and what is above or below it
constexpr double kLineOverhang = 10;     // of a double line beyond the outer branches
constexpr double kJumpLength = 30;       // of a jump arrow
constexpr double kLoopDrop = 16;         // below a bar, where a loop turns towards its channel
constexpr double kLoopChannel = 20;      // room left of a column for its loop line
constexpr double kMinHalfWidth = 20;     // of a column, on either side of its axis
constexpr double kActionGap = 20;        // between a step box and its first action box
constexpr double kTextPadding = 12;      // in a cell, around its text
constexpr double kMinTextCell = 40;
constexpr double kMinQualifierCell = 24;

enum class ItemKind { Step, Transition, Selection, Parallel, Back, Reference };

struct Item {
    ItemKind kind = ItemKind::Step;
    int number = 0;     // Step, Reference: the step; Transition: the transition; Back: the target step
    int transition = 0; // Back: the transition; Parallel: the opening transition (0: none)
    int closing = 0;    // Parallel: the closing transition (0: none); Selection: the join step (0: none)
    std::vector<int> branches; // Selection, Parallel: sequence indices, in branch order
    bool loop = false;         // Back: drawn as a loop line (else a jump)
    int channel = 0;           // Back drawn as a loop: 1 for the channel nearest the column, 2 the next...
    int mainBranch = -1;       // Selection: the branch the sequence goes on with below it (-1: none)
    bool forceJump = false;
    // Measured, relative to the column's axis.
    double left = 0;
    double right = 0;
    double height = 0;
    std::vector<double> branchAxis;
    double branchHeight = 0;
};

// The room reserved beside a column for a text of this width.
double reserved(double width)
{
    return width <= 0 ? 0 : std::ceil(width / kGrafcetLabelReserve) * kGrafcetLabelReserve;
}

Item makeItem(ItemKind kind, int number = 0)
{
    Item item;
    item.kind = kind;
    item.number = number;
    return item;
}

struct Sequence {
    std::vector<Item> items;
    bool joins = false; // a selection branch that ends on its selection's convergence
    int parent = -1;    // the sequence holding the block this one is a branch of
    int parentItem = -1;
    int parentBranch = -1;
    bool hasLoop = false;  // a loop line goes up beside it
    int channels = 0;      // loop channels beside it
    bool crossed = false;  // a loop line to an outer column passes through it
    double contentLeft = 0;
    double left = 0;
    double right = 0;
    double height = 0;
    double axis = 0; // placed
};

struct Context {
    int join = 0;              // the step this selection branch converges on (0: none)
    std::vector<int> stops;    // joins of the enclosing selections: reached from inside, they are jumps
    bool inParallel = false;   // a branch of a parallel section ends before a convergence
};

struct End {
    bool isStep = true;
    int number = 0;
    std::vector<Point> path;
    bool fromReference = false;
    Rect referenceRect;
};

void extend(std::vector<Point>& path, Point point)
{
    if (!path.empty() && path.back() == point)
        return;
    // Collinear with the last stretch: the stretch grows.
    if (path.size() >= 2) {
        const Point& a = path[path.size() - 2];
        const Point& b = path.back();
        const bool vertical = a.x == b.x && b.x == point.x && ((b.y - a.y) * (point.y - b.y) > 0);
        const bool horizontal = a.y == b.y && b.y == point.y && ((b.x - a.x) * (point.x - b.x) > 0);
        if (vertical || horizontal) {
            path.back() = point;
            return;
        }
    }
    path.push_back(point);
}

class Builder {
public:
    Builder(const Grafcet& grafcet, const TextMeasure& measure) : m_grafcet(grafcet), m_measure(measure)
    {
        const auto& steps = grafcet.steps();
        for (std::size_t i = 0; i < steps.size(); ++i)
            m_stepIndex[steps[i].number] = static_cast<int>(i);
        m_placed.assign(steps.size(), false);
        m_outgoing.resize(steps.size());
        const auto& transitions = grafcet.transitions();
        m_drawn.assign(transitions.size(), false);
        m_detached.assign(transitions.size(), false);
        for (std::size_t t = 0; t < transitions.size(); ++t) {
            m_transitionIndex[transitions[t].number] = static_cast<int>(t);
            for (int up : transitions[t].upstream) {
                const int s = stepIndex(up);
                if (s >= 0)
                    m_outgoing[static_cast<std::size_t>(s)].push_back(static_cast<int>(t));
            }
        }
        m_stamp.assign(steps.size(), 0);
        m_roundOf.assign(steps.size(), 0);
        m_reachCount.assign(steps.size(), 0);
        m_reachSum.assign(steps.size(), 0);
        m_distance.assign(steps.size(), 0);
    }

    GrafcetLayout build()
    {
        std::vector<int> roots;
        const auto& steps = m_grafcet.steps();
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t i = 0; i < steps.size(); ++i) {
                if (m_placed[i] || (pass == 0 && !steps[i].initial))
                    continue;
                const int seq = newSequence();
                roots.push_back(seq);
                parseSteps(seq, steps[i].number, Context{});
            }
        }
        const auto& transitions = m_grafcet.transitions();
        for (std::size_t t = 0; t < transitions.size(); ++t) {
            if (!m_drawn[t])
                roots.push_back(detachedColumn(static_cast<int>(t)));
        }
        resolveLoops();
        for (int root : roots)
            measure(root);

        GrafcetLayout layout;
        layout.steps.resize(steps.size());
        layout.transitions.resize(transitions.size());
        m_layout = &layout;
        double x = kGrafcetMargin;
        for (int root : roots) {
            const Sequence& seq = m_sequences[static_cast<std::size_t>(root)];
            const double axis = x + seq.left;
            const double right = seq.right;
            place(root, axis, kGrafcetMargin, {});
            x = axis + right + kGrafcetColumnGap;
        }
        for (std::size_t t = 0; t < transitions.size(); ++t) {
            layout.transitions[t].number = transitions[t].number;
            layout.transitions[t].detached = m_detached[t];
        }
        layout.boundingRect = bounds(layout);
        m_layout = nullptr;
        return layout;
    }

private:
    int stepIndex(int number) const
    {
        const auto found = m_stepIndex.find(number);
        return found == m_stepIndex.end() ? -1 : found->second;
    }
    const GrafcetTransition& transitionAt(int index) const
    {
        return m_grafcet.transitions()[static_cast<std::size_t>(index)];
    }
    int transitionIndex(int number) const { return m_transitionIndex.at(number); }
    bool placed(int stepNumber) const
    {
        const int s = stepIndex(stepNumber);
        return s < 0 || m_placed[static_cast<std::size_t>(s)];
    }
    double width(std::string_view text) const { return std::max(0.0, m_measure(text)); }
    double labelWidth(std::string_view text) const { return width(text) + 8; }

    int newSequence(int parent = -1, int parentItem = -1, int parentBranch = -1)
    {
        Sequence seq;
        seq.parent = parent;
        seq.parentItem = parentItem;
        seq.parentBranch = parentBranch;
        m_sequences.push_back(std::move(seq));
        return static_cast<int>(m_sequences.size()) - 1;
    }
    Sequence& sequence(int index) { return m_sequences[static_cast<std::size_t>(index)]; }

    void addItem(int seq, Item item)
    {
        Sequence& s = sequence(seq);
        const int itemIndex = static_cast<int>(s.items.size());
        for (std::size_t b = 0; b < item.branches.size(); ++b) {
            Sequence& branch = sequence(item.branches[b]);
            branch.parent = seq;
            branch.parentItem = itemIndex;
            branch.parentBranch = static_cast<int>(b);
        }
        if (item.kind == ItemKind::Step)
            m_stepPlace[item.number] = {seq, itemIndex};
        sequence(seq).items.push_back(std::move(item));
    }

    static bool stops(const Context& context, int step)
    {
        return std::find(context.stops.begin(), context.stops.end(), step) != context.stops.end();
    }

    // Steps from `step` down the column, until the sequence ends.
    void parseSteps(int seq, int step, const Context& context)
    {
        while (true) {
            const int s = stepIndex(step);
            m_placed[static_cast<std::size_t>(s)] = true;
            addItem(seq, makeItem(ItemKind::Step, step));
            std::vector<int> owned;
            bool convergence = false;
            for (int t : m_outgoing[static_cast<std::size_t>(s)]) {
                if (m_drawn[static_cast<std::size_t>(t)])
                    continue;
                if (transitionAt(t).upstream.size() == 1)
                    owned.push_back(t);
                else
                    convergence = true;
            }
            // In a parallel branch, a step with a transition to a convergence
            // ends the branch unless the sequence goes on to new steps (then
            // that transition is detached).
            const bool goesOn = std::any_of(owned.begin(), owned.end(), [&](int t) {
                return std::any_of(transitionAt(t).downstream.begin(), transitionAt(t).downstream.end(),
                                   [&](int d) { return !placed(d) && !stops(context, d) && d != context.join; });
            });
            if (owned.empty() || (convergence && context.inParallel && !goesOn))
                return; // the end of a branch of a parallel section, or of the sequence
            if (owned.size() == 1) {
                const auto next = afterTransition(seq, owned.front(), context);
                if (!next)
                    return;
                step = *next;
                continue;
            }
            // A selection divergence.
            Context inner;
            inner.stops = context.stops;
            if (context.join != 0)
                inner.stops.push_back(context.join);
            inner.join = findJoin(owned, inner.stops);
            inner.inParallel = context.inParallel;
            Item selection = makeItem(ItemKind::Selection, step);
            selection.closing = inner.join;
            // Without a convergence the sequence goes on below the
            // selection with the first branch that leads to new steps, as
            // the sheet draws it: the step's column goes straight down that
            // branch and the others (an exit step added beside) stand to
            // its right. Branches that go back together with others keep
            // their place to its left, where their one convergence is
            // drawn (else the last such branch continues the column). Its
            // first transition stands with the other branches.
            if (inner.join == 0) {
                std::vector<int> backs; // by branch, where a plain sequence goes back to (0: not so)
                for (int t : owned)
                    backs.push_back(goesBackTo(t));
                int lastSharingBack = -1;
                std::vector<bool> continues(owned.size(), false);
                for (std::size_t b = 0; b < owned.size(); ++b) {
                    const auto& down = transitionAt(owned[b]).downstream;
                    // A branch going back where another one does ends on their convergence.
                    const bool sharesBack = backs[b] != 0 && std::count(backs.begin(), backs.end(), backs[b]) > 1;
                    if (sharesBack)
                        lastSharingBack = static_cast<int>(b);
                    continues[b] = !sharesBack && std::any_of(down.begin(), down.end(), [&](int d) {
                        return !placed(d) && !stops(inner, d);
                    });
                }
                int firstRight = -1;
                int last = -1;
                for (std::size_t b = 0; b < owned.size(); ++b) {
                    if (!continues[b])
                        continue;
                    last = static_cast<int>(b);
                    if (last > lastSharingBack && firstRight < 0)
                        firstRight = last;
                }
                selection.mainBranch = firstRight >= 0 ? firstRight : last;
            }
            bool joined = false;
            int mainBar = -1;
            for (std::size_t b = 0; b < owned.size(); ++b) {
                const int branch = newSequence();
                selection.branches.push_back(branch);
                if (static_cast<int>(b) == selection.mainBranch) {
                    mainBar = branch;
                    continue; // after the other branches: they take the steps they reach first
                }
                if (const auto next = afterTransition(branch, owned[b], inner))
                    parseSteps(branch, *next, inner);
                joined = joined || sequence(branch).joins;
            }
            if (inner.join == 0) {
                if (const int target = commonBack(selection); target != 0) {
                    // One convergence, then one link back, instead of one
                    // jump per branch: the main branch becomes a plain one.
                    if (mainBar >= 0) {
                        const int main = selection.mainBranch;
                        selection.mainBranch = -1;
                        if (const auto next = afterTransition(mainBar, owned[static_cast<std::size_t>(main)], inner))
                            parseSteps(mainBar, *next, inner);
                    }
                    mergeBacks(selection, target);
                    addItem(seq, std::move(selection));
                    Item back = makeItem(ItemKind::Back, target);
                    addItem(seq, std::move(back));
                    m_backs.emplace_back(seq, static_cast<int>(sequence(seq).items.size()) - 1);
                    return;
                }
            }
            if (mainBar >= 0) {
                // The main branch holds its bar; what follows is the sequence's.
                addItem(seq, std::move(selection));
                const auto next = afterTransition(seq, owned[static_cast<std::size_t>(sequence(seq).items.back().mainBranch)],
                                                  context, mainBar);
                if (!next)
                    return;
                step = *next;
                continue;
            }
            addItem(seq, std::move(selection));
            if (!joined || inner.join == 0 || placed(inner.join))
                return;
            step = inner.join;
        }
    }

    // Where the branch starting with transition t (an index) goes back to
    // when it is a plain sequence ending on a placed step; 0 otherwise.
    int goesBackTo(int t) const
    {
        for (std::size_t walked = 0; walked <= m_grafcet.steps().size(); ++walked) {
            const GrafcetTransition& transition = transitionAt(t);
            if (transition.downstream.size() != 1)
                return 0;
            const int d = transition.downstream.front();
            if (placed(d))
                return stepIndex(d) >= 0 ? d : 0;
            const std::vector<int>& next = m_outgoing[static_cast<std::size_t>(stepIndex(d))];
            if (next.size() != 1 || transitionAt(next.front()).upstream.size() != 1)
                return 0;
            t = next.front();
        }
        return 0;
    }

    // The placed step that two or more branches of the selection end by
    // going back to, side by side: no branch between them goes on below the
    // selection or ends otherwise than by going back. The one most branches
    // go back to, the leftmost of those; 0 for none.
    int commonBack(const Item& selection) const
    {
        std::vector<int> targets; // by branch: where it goes back to, 0 when it does not end so
        for (std::size_t b = 0; b < selection.branches.size(); ++b) {
            const Sequence& branch = m_sequences[static_cast<std::size_t>(selection.branches[b])];
            // Not the link back of an inner convergence (no transition of its own): its bars stand elsewhere.
            const bool back = static_cast<int>(b) != selection.mainBranch && !branch.items.empty()
                           && branch.items.back().kind == ItemKind::Back && !branch.items.back().forceJump
                           && branch.items.back().transition != 0;
            targets.push_back(back ? branch.items.back().number : 0);
        }
        int best = 0;
        std::size_t bestCount = 1;
        for (int target : targets) {
            if (target == 0)
                continue;
            std::size_t first = targets.size();
            std::size_t last = 0;
            for (std::size_t b = 0; b < targets.size(); ++b) {
                if (targets[b] == target) {
                    first = std::min(first, b);
                    last = b;
                }
            }
            bool between = true;
            for (std::size_t b = first; b <= last; ++b) {
                const Sequence& branch = m_sequences[static_cast<std::size_t>(selection.branches[b])];
                between = between && static_cast<int>(b) != selection.mainBranch && !branch.items.empty()
                       && branch.items.back().kind == ItemKind::Back;
            }
            const std::size_t count = static_cast<std::size_t>(std::count(targets.begin(), targets.end(), target));
            if (between && count > bestCount) {
                best = target;
                bestCount = count;
            }
        }
        return best;
    }

    // The branches going back to `target` end on the selection's convergence instead.
    void mergeBacks(Item& selection, int target)
    {
        for (int b : selection.branches) {
            Sequence& branch = sequence(b);
            if (branch.items.empty() || branch.items.back().kind != ItemKind::Back || branch.items.back().number != target
                || branch.items.back().forceJump || branch.items.back().transition == 0)
                continue;
            const std::pair<int, int> place(b, static_cast<int>(branch.items.size()) - 1);
            m_backs.erase(std::remove(m_backs.begin(), m_backs.end(), place), m_backs.end());
            branch.items.pop_back();
            branch.joins = true;
        }
        selection.closing = target;
    }

    // Draws the transition (and the parallel sections it opens) in the
    // sequence; returns the step the sequence goes on with, if any. The
    // first bar goes to barSeq when given (the main branch of a selection).
    std::optional<int> afterTransition(int seq, int t, const Context& context, int barSeq = -1)
    {
        while (true) {
            m_drawn[static_cast<std::size_t>(t)] = true;
            const GrafcetTransition& transition = transitionAt(t);
            addItem(barSeq >= 0 ? barSeq : seq, makeItem(ItemKind::Transition, transition.number));
            barSeq = -1;
            if (transition.downstream.size() == 1) {
                const int d = transition.downstream.front();
                if (context.join != 0 && d == context.join) {
                    sequence(seq).joins = true;
                    return std::nullopt;
                }
                if (placed(d) || stops(context, d)) {
                    Item back = makeItem(ItemKind::Back, d);
                    back.transition = transition.number;
                    back.forceJump = !placed(d); // an outer join, placed below: only a jump
                    addItem(seq, std::move(back));
                    m_backs.emplace_back(seq, static_cast<int>(sequence(seq).items.size()) - 1);
                    return std::nullopt;
                }
                return d;
            }
            // A simultaneous divergence: one branch per downstream step.
            Context inner;
            inner.stops = context.stops;
            if (context.join != 0)
                inner.stops.push_back(context.join);
            inner.inParallel = true;
            Item parallel = makeItem(ItemKind::Parallel);
            parallel.transition = transition.number;
            std::vector<int> ends; // the steps that end the branches
            for (int d : transition.downstream) {
                const int branch = newSequence();
                parallel.branches.push_back(branch);
                if (placed(d) || stops(inner, d)) {
                    Item back = makeItem(ItemKind::Back, d);
                    back.transition = transition.number;
                    back.forceJump = true;
                    sequence(branch).items.push_back(std::move(back));
                    continue;
                }
                parseSteps(branch, d, inner);
                branchEnds(branch, ends);
            }
            // The convergence: a transition from the last steps of some of the branches.
            int closing = -1;
            for (int end : ends) {
                if (closing >= 0)
                    break;
                for (int c : m_outgoing[static_cast<std::size_t>(stepIndex(end))]) {
                    const GrafcetTransition& candidate = transitionAt(c);
                    if (m_drawn[static_cast<std::size_t>(c)] || candidate.upstream.size() < 2)
                        continue;
                    const bool fits = std::all_of(candidate.upstream.begin(), candidate.upstream.end(),
                                                  [&](int up) { return std::find(ends.begin(), ends.end(), up) != ends.end(); });
                    if (fits) {
                        closing = c;
                        break;
                    }
                }
            }
            if (closing >= 0)
                parallel.closing = transitionAt(closing).number;
            addItem(seq, std::move(parallel));
            if (closing < 0)
                return std::nullopt;
            t = closing;
        }
    }

    // The steps whose links leave the bottom of the sequence: its last step,
    // or those ending the branches of a last selection that has no
    // convergence (nothing is below them: their links go down freely).
    void branchEnds(int seqIndex, std::vector<int>& ends) const
    {
        const Sequence& seq = m_sequences[static_cast<std::size_t>(seqIndex)];
        if (seq.items.empty())
            return;
        const Item& last = seq.items.back();
        if (last.kind == ItemKind::Step) {
            ends.push_back(last.number);
        } else if (last.kind == ItemKind::Selection && !joined(last)) {
            for (int branch : last.branches)
                branchEnds(branch, ends);
        }
    }

    bool joined(const Item& selection) const
    {
        return selection.closing != 0
            && std::any_of(selection.branches.begin(), selection.branches.end(),
                           [&](int b) { return m_sequences[static_cast<std::size_t>(b)].joins; });
    }

    // Where the branches of a selection meet: the step most of them reach
    // (going down, not through placed steps or outer joins), the nearest.
    int findJoin(const std::vector<int>& branches, const std::vector<int>& stopSteps)
    {
        ++m_round;
        std::vector<int> touched;
        for (int t : branches) {
            ++m_stampValue;
            std::vector<int> queue;
            for (int d : transitionAt(t).downstream) {
                const int s = stepIndex(d);
                if (s < 0 || m_placed[static_cast<std::size_t>(s)] || std::find(stopSteps.begin(), stopSteps.end(), d) != stopSteps.end())
                    continue;
                if (m_stamp[static_cast<std::size_t>(s)] == m_stampValue)
                    continue;
                m_stamp[static_cast<std::size_t>(s)] = m_stampValue;
                m_distance[static_cast<std::size_t>(s)] = 1;
                queue.push_back(s);
            }
            for (std::size_t head = 0; head < queue.size(); ++head) {
                const int s = queue[head];
                const std::size_t su = static_cast<std::size_t>(s);
                if (m_roundOf[su] != m_round) {
                    m_roundOf[su] = m_round;
                    m_reachCount[su] = 0;
                    m_reachSum[su] = 0;
                    touched.push_back(s);
                }
                ++m_reachCount[su];
                m_reachSum[su] += m_distance[su];
                for (int next : m_outgoing[su]) {
                    for (int d : transitionAt(next).downstream) {
                        const int n = stepIndex(d);
                        if (n < 0 || m_placed[static_cast<std::size_t>(n)]
                            || m_stamp[static_cast<std::size_t>(n)] == m_stampValue
                            || std::find(stopSteps.begin(), stopSteps.end(), d) != stopSteps.end())
                            continue;
                        m_stamp[static_cast<std::size_t>(n)] = m_stampValue;
                        m_distance[static_cast<std::size_t>(n)] = m_distance[su] + 1;
                        queue.push_back(n);
                    }
                }
            }
        }
        int best = -1;
        for (int s : touched) {
            const std::size_t su = static_cast<std::size_t>(s);
            if (m_reachCount[su] < 2)
                continue;
            if (best < 0) {
                best = s;
                continue;
            }
            const std::size_t bu = static_cast<std::size_t>(best);
            if (m_reachCount[su] > m_reachCount[bu]
                || (m_reachCount[su] == m_reachCount[bu]
                    && (m_reachSum[su] < m_reachSum[bu] || (m_reachSum[su] == m_reachSum[bu] && s < best))))
                best = s;
        }
        return best < 0 ? 0 : m_grafcet.steps()[static_cast<std::size_t>(best)].number;
    }

    // A transition the structure did not draw, in a column of its own.
    int detachedColumn(int t)
    {
        m_drawn[static_cast<std::size_t>(t)] = true;
        m_detached[static_cast<std::size_t>(t)] = true;
        const GrafcetTransition& transition = transitionAt(t);
        const int seq = newSequence();
        if (transition.upstream.size() == 1) {
            addItem(seq, makeItem(ItemKind::Reference, transition.upstream.front()));
        } else {
            Item parallel = makeItem(ItemKind::Parallel);
            parallel.closing = transition.number;
            for (int up : transition.upstream) {
                const int branch = newSequence();
                sequence(branch).items.push_back(makeItem(ItemKind::Reference, up));
                parallel.branches.push_back(branch);
            }
            addItem(seq, std::move(parallel));
        }
        addItem(seq, makeItem(ItemKind::Transition, transition.number));
        const auto jump = [&](int target) {
            Item back = makeItem(ItemKind::Back, target);
            back.transition = transition.number;
            back.forceJump = true;
            return back;
        };
        if (transition.downstream.size() == 1) {
            addItem(seq, jump(transition.downstream.front()));
        } else {
            Item parallel = makeItem(ItemKind::Parallel);
            parallel.transition = transition.number;
            for (int d : transition.downstream) {
                const int branch = newSequence();
                sequence(branch).items.push_back(jump(d));
                parallel.branches.push_back(branch);
            }
            addItem(seq, std::move(parallel));
        }
        return seq;
    }

    // A transition back to a placed step is a loop line when the target is
    // in a column the transition's branch reaches through first branches of
    // selections only, and its line neither interleaves with another loop
    // line of that column nor passes a column that has loop lines of its
    // own; otherwise a jump. Nested loop lines get channels further out.
    void resolveLoops()
    {
        struct Accepted {
            int start = 0; // the target step's item in the column
            int end = 0;   // the item holding the transition
            Item* back = nullptr;
        };
        std::map<int, std::vector<Accepted>> accepted; // by column
        for (const auto& [seqIndex, itemIndex] : m_backs) {
            Item& back = sequence(seqIndex).items[static_cast<std::size_t>(itemIndex)];
            if (back.forceJump)
                continue;
            const auto place = m_stepPlace.find(back.number);
            if (place == m_stepPlace.end())
                continue;
            const int target = place->second.first;
            std::vector<int> crossed;
            int current = seqIndex;
            int sourceItem = itemIndex;
            bool ok = true;
            while (current != target) {
                const Sequence& seq = sequence(current);
                if (seq.parent < 0 || seq.parentBranch != 0
                    || sequence(seq.parent).items[static_cast<std::size_t>(seq.parentItem)].kind != ItemKind::Selection) {
                    ok = false;
                    break;
                }
                crossed.push_back(current);
                sourceItem = seq.parentItem;
                current = seq.parent;
            }
            if (!ok || sequence(target).crossed)
                continue;
            if (std::any_of(crossed.begin(), crossed.end(), [&](int s) { return sequence(s).hasLoop; }))
                continue;
            const int start = place->second.second;
            const int end = sourceItem;
            auto& lines = accepted[target];
            // Two lines from inside the same block of the column (branches of
            // one selection) could nest either way round: which one leaves
            // lower is not known yet, and the wrong one outside would cross
            // the other. Only one of them is a loop line.
            const bool interleaves = std::any_of(lines.begin(), lines.end(), [&](const Accepted& a) {
                return (a.start < start && start < a.end && a.end < end) || (start < a.start && a.start < end && end < a.end)
                    || a.end == end;
            });
            if (interleaves)
                continue;
            lines.push_back({start, end, &back});
            sequence(target).hasLoop = true;
            for (int s : crossed)
                sequence(s).crossed = true;
            back.loop = true;
        }
        for (auto& [target, lines] : accepted) {
            std::sort(lines.begin(), lines.end(), [](const Accepted& a, const Accepted& b) {
                return a.end - a.start < b.end - b.start;
            });
            int channels = 0;
            for (std::size_t i = 0; i < lines.size(); ++i) {
                int level = 1;
                for (std::size_t j = 0; j < i; ++j) {
                    if (lines[j].start >= lines[i].start && lines[j].end <= lines[i].end)
                        level = std::max(level, lines[j].back->channel + 1);
                }
                lines[i].back->channel = level;
                channels = std::max(channels, level);
            }
            sequence(target).channels = channels;
        }
    }

    double stepSize(int number) const
    {
        return std::max(kGrafcetStepSize, width(std::to_string(number)) + kTextPadding);
    }

    struct ActionSizes {
        std::vector<ActionParts> parts;
        std::vector<double> qualifierWidth;
        std::vector<double> textWidth;
        double total = 0;
        bool conditions = false;
    };

    ActionSizes actionSizes(const GrafcetStep& step) const
    {
        ActionSizes sizes;
        for (const GrafcetAction& action : step.actions) {
            ActionParts parts = splitAction(action);
            const double q = parts.qualifier.empty() ? 0 : std::max(kMinQualifierCell, width(parts.qualifier) + kTextPadding);
            double text = std::max(kMinTextCell, width(parts.text) + kTextPadding);
            if (!parts.condition.empty()) {
                text = std::max(text, labelWidth(parts.condition));
                sizes.conditions = true;
            }
            sizes.qualifierWidth.push_back(q);
            sizes.textWidth.push_back(text);
            sizes.total += q + text;
            sizes.parts.push_back(std::move(parts));
        }
        return sizes;
    }

    const GrafcetStep& stepOf(int number) const
    {
        return m_grafcet.steps()[static_cast<std::size_t>(stepIndex(number))];
    }

    void measure(int seqIndex)
    {
        double contentLeft = kMinHalfWidth;
        double right = kMinHalfWidth;
        double height = 0;
        for (std::size_t i = 0; i < sequence(seqIndex).items.size(); ++i) {
            Item& item = sequence(seqIndex).items[i];
            switch (item.kind) {
            case ItemKind::Step: {
                const double size = stepSize(item.number);
                const ActionSizes actions = actionSizes(stepOf(item.number));
                item.left = size / 2;
                item.right = size / 2 + (actions.parts.empty() ? 0 : kActionGap + reserved(actions.total));
                const double below = actions.conditions ? kGrafcetActionHeight / 2 + 2 + kGrafcetConditionHeight
                                                        : kGrafcetActionHeight / 2;
                item.height = kStepTopGap + size / 2 + std::max(size / 2, below);
                break;
            }
            case ItemKind::Transition:
                item.left = kGrafcetBarLength / 2;
                item.right = kGrafcetBarLength / 2 + kLabelGap
                           + reserved(labelWidth(m_grafcet.transitions()[static_cast<std::size_t>(transitionIndex(item.number))].receptivity));
                item.height = kTransitionHeight;
                break;
            case ItemKind::Back:
                item.left = kGrafcetBarLength / 2;
                item.right = item.loop ? kGrafcetBarLength / 2 : kLabelGap + labelWidth(std::to_string(item.number));
                item.height = item.loop ? kLoopDrop + 4 : kJumpLength + 4;
                break;
            case ItemKind::Reference: {
                const double w = labelWidth(std::to_string(item.number));
                item.left = w / 2;
                item.right = w / 2;
                item.height = kGrafcetLabelHeight;
                break;
            }
            case ItemKind::Selection:
            case ItemKind::Parallel: {
                item.branchAxis.clear();
                item.branchHeight = 0;
                double axis = 0;
                double previousRight = 0;
                bool anyJoin = false;
                for (std::size_t b = 0; b < item.branches.size(); ++b) {
                    measure(item.branches[b]);
                    const Sequence& branch = sequence(item.branches[b]);
                    if (b > 0)
                        axis += previousRight + kGrafcetBranchGap + branch.left;
                    item.branchAxis.push_back(axis);
                    previousRight = branch.right;
                    item.branchHeight = std::max(item.branchHeight, branch.height);
                    anyJoin = anyJoin || branch.joins;
                }
                // A selection without convergence goes on with its main
                // branch: that one stands under the column's axis, so the
                // sequence stays straight (a loop branch beside it).
                if (item.kind == ItemKind::Selection && item.mainBranch >= 0) {
                    const double offset = item.branchAxis[static_cast<std::size_t>(item.mainBranch)];
                    for (double& x : item.branchAxis)
                        x -= offset;
                    axis -= offset;
                }
                item.left = item.branches.empty() ? kMinHalfWidth
                                                  : sequence(item.branches.front()).left - item.branchAxis.front();
                item.right = axis + previousRight;
                if (item.kind == ItemKind::Selection) {
                    item.height = kLineMargin + item.branchHeight + (anyJoin && item.closing != 0 ? kLineMargin : 0);
                } else {
                    item.height = (item.transition != 0 ? kLineMargin + kDoubleLineGap : 0) + item.branchHeight
                                + (item.closing != 0 ? kLineMargin + kDoubleLineGap : 0);
                }
                break;
            }
            }
            contentLeft = std::max(contentLeft, item.left);
            right = std::max(right, item.right);
            height += item.height;
        }
        Sequence& seq = sequence(seqIndex);
        seq.contentLeft = contentLeft;
        seq.left = contentLeft + seq.channels * kLoopChannel;
        seq.right = right;
        seq.height = height;
    }

    void addLink(GrafcetLinkLayout::Kind kind, const End& end, int other, std::vector<Point> path,
                 GrafcetLinkLayout::Ending ending = GrafcetLinkLayout::Ending::Plain, Rect label = {})
    {
        GrafcetLinkLayout link;
        link.kind = kind;
        if (kind == GrafcetLinkLayout::Kind::StepToTransition) {
            link.step = end.number;
            link.transition = other;
        } else {
            link.transition = end.number;
            link.step = other;
        }
        link.route = std::move(path);
        link.ending = ending;
        link.labelRect = label;
        link.fromReference = end.fromReference;
        link.referenceRect = end.referenceRect;
        m_layout->links.push_back(std::move(link));
    }

    // Places the sequence with its axis at x, from y down; `ends` are the
    // open links arriving from above; returns those leaving its bottom.
    std::vector<End> place(int seqIndex, double axis, double y, std::vector<End> ends)
    {
        sequence(seqIndex).axis = axis;
        for (std::size_t i = 0; i < sequence(seqIndex).items.size(); ++i) {
            const Item item = sequence(seqIndex).items[i]; // a copy: placing may not touch this item, but stays safe
            switch (item.kind) {
            case ItemKind::Step:
                ends = placeStep(item.number, axis, y, std::move(ends));
                break;
            case ItemKind::Transition: {
                const double barY = y + kTransitionHeight / 2;
                const auto& transition = m_grafcet.transitions()[static_cast<std::size_t>(transitionIndex(item.number))];
                for (End& end : ends) {
                    if (!end.isStep)
                        continue;
                    extend(end.path, {axis, barY});
                    addLink(GrafcetLinkLayout::Kind::StepToTransition, end, item.number, std::move(end.path));
                }
                GrafcetTransitionLayout& layout = m_layout->transitions[static_cast<std::size_t>(transitionIndex(item.number))];
                layout.barCenter = {axis, barY};
                layout.labelRect = {axis + kGrafcetBarLength / 2 + kLabelGap, barY - kGrafcetLabelHeight / 2,
                                    labelWidth(transition.receptivity), kGrafcetLabelHeight};
                End end;
                end.isStep = false;
                end.number = item.number;
                end.path = {{axis, barY}};
                ends = {std::move(end)};
                break;
            }
            case ItemKind::Back:
                for (End& end : ends) {
                    if (end.isStep)
                        continue;
                    if (item.loop) {
                        const auto [targetSeq, targetItem] = m_stepPlace.at(item.number);
                        (void)targetItem;
                        const double targetAxis = sequence(targetSeq).axis;
                        const double targetChannel = targetAxis - sequence(targetSeq).contentLeft
                                                   - kLoopChannel * (item.channel - 0.5);
                        const Rect box = m_layout->steps[static_cast<std::size_t>(stepIndex(item.number))].box;
                        const double turn = y + kLoopDrop;
                        const double arrive = box.top() - kStepTopGap / 2;
                        extend(end.path, {axis, turn});
                        extend(end.path, {targetChannel, turn});
                        extend(end.path, {targetChannel, arrive});
                        extend(end.path, {targetAxis, arrive});
                        extend(end.path, {targetAxis, box.top()});
                        addLink(GrafcetLinkLayout::Kind::TransitionToStep, end, item.number, std::move(end.path),
                                GrafcetLinkLayout::Ending::Loop);
                    } else {
                        extend(end.path, {axis, y + kJumpLength});
                        const Rect label{axis + kLabelGap, y + kJumpLength - kGrafcetLabelHeight,
                                         labelWidth(std::to_string(item.number)), kGrafcetLabelHeight};
                        addLink(GrafcetLinkLayout::Kind::TransitionToStep, end, item.number, std::move(end.path),
                                GrafcetLinkLayout::Ending::Jump, label);
                    }
                }
                ends.clear();
                break;
            case ItemKind::Reference: {
                const double w = labelWidth(std::to_string(item.number));
                End end;
                end.isStep = true;
                end.number = item.number;
                end.fromReference = true;
                end.referenceRect = {axis - w / 2, y, w, kGrafcetLabelHeight};
                end.path = {{axis, y + kGrafcetLabelHeight}};
                ends = {std::move(end)};
                break;
            }
            case ItemKind::Selection:
                ends = placeSelection(item, axis, y, std::move(ends));
                break;
            case ItemKind::Parallel:
                ends = placeParallel(item, axis, y, std::move(ends));
                break;
            }
            y += item.height;
        }
        return ends;
    }

    std::vector<End> placeStep(int number, double axis, double y, std::vector<End> ends)
    {
        const GrafcetStep& step = stepOf(number);
        GrafcetStepLayout& layout = m_layout->steps[static_cast<std::size_t>(stepIndex(number))];
        const double size = stepSize(number);
        layout.number = number;
        layout.initial = step.initial;
        layout.box = {axis - size / 2, y + kStepTopGap, size, size};
        for (End& end : ends) {
            if (end.isStep)
                continue;
            extend(end.path, {axis, layout.box.top()});
            addLink(GrafcetLinkLayout::Kind::TransitionToStep, end, number, std::move(end.path));
        }
        const ActionSizes sizes = actionSizes(step);
        const double cy = layout.box.center().y;
        double x = layout.box.right() + kActionGap;
        if (!sizes.parts.empty())
            layout.actionLink = {{layout.box.right(), cy}, {x, cy}};
        for (std::size_t a = 0; a < sizes.parts.size(); ++a) {
            GrafcetActionLayout action;
            action.index = static_cast<int>(a);
            action.timing = step.actions[a].timing;
            const double q = sizes.qualifierWidth[a];
            const double t = sizes.textWidth[a];
            const double top = cy - kGrafcetActionHeight / 2;
            action.box = {x, top, q + t, kGrafcetActionHeight};
            action.qualifierCell = {x, top, q, q > 0 ? kGrafcetActionHeight : 0};
            action.textCell = {x + q, top, t, kGrafcetActionHeight};
            action.qualifier = sizes.parts[a].qualifier;
            action.text = sizes.parts[a].text;
            action.condition = sizes.parts[a].condition;
            if (!action.condition.empty())
                action.conditionRect = {x + q, action.box.bottom() + 2, labelWidth(action.condition), kGrafcetConditionHeight};
            layout.actions.push_back(std::move(action));
            x += q + t;
        }
        End end;
        end.isStep = true;
        end.number = number;
        end.path = {{axis, layout.box.bottom()}};
        return {std::move(end)};
    }

    std::vector<End> placeSelection(const Item& item, double axis, double y, std::vector<End> ends)
    {
        const double lineY = y + kLineMargin;
        GrafcetBranchLineLayout divergence;
        divergence.kind = GrafcetBranchLineLayout::Kind::SelectionDivergence;
        divergence.y = lineY;
        divergence.left = axis + item.branchAxis.front();
        divergence.right = axis + item.branchAxis.back();
        divergence.step = item.number;
        const double convergenceY = lineY + item.branchHeight + kLineMargin;
        GrafcetBranchLineLayout convergence;
        convergence.kind = GrafcetBranchLineLayout::Kind::SelectionConvergence;
        convergence.y = convergenceY;
        convergence.left = axis;
        convergence.right = axis;
        convergence.step = item.closing;
        std::vector<End> result;
        std::vector<End> passing; // the last steps of branches that do not converge
        std::vector<End> mainEnds; // the bar of the branch the sequence goes on with
        for (std::size_t b = 0; b < item.branches.size(); ++b) {
            const double branchAxis = axis + item.branchAxis[b];
            std::vector<End> into;
            for (const End& end : ends) {
                if (!end.isStep)
                    continue;
                End copy = end;
                extend(copy.path, {axis, lineY});
                extend(copy.path, {branchAxis, lineY});
                into.push_back(std::move(copy));
            }
            const Sequence& branch = sequence(item.branches[b]);
            if (!branch.items.empty() && branch.items.front().kind == ItemKind::Transition)
                divergence.branches.push_back(branch.items.front().number);
            const bool joins = branch.joins && item.closing != 0;
            std::vector<End> out = place(item.branches[b], branchAxis, lineY, std::move(into));
            if (static_cast<int>(b) == item.mainBranch) {
                for (End& end : out) {
                    if (!end.isStep)
                        mainEnds.push_back(std::move(end));
                }
                continue;
            }
            if (!joins) {
                for (End& end : out) {
                    if (end.isStep)
                        passing.push_back(std::move(end));
                }
                continue;
            }
            for (End& end : out) {
                if (end.isStep)
                    continue;
                extend(end.path, {branchAxis, convergenceY});
                extend(end.path, {axis, convergenceY});
                convergence.left = std::min(convergence.left, branchAxis);
                convergence.right = std::max(convergence.right, branchAxis);
                convergence.branches.push_back(end.number);
                result.push_back(std::move(end));
            }
        }
        m_layout->lines.push_back(std::move(divergence));
        if (item.mainBranch >= 0)
            return mainEnds;
        if (convergence.branches.empty())
            return passing; // a parallel section's convergence may take them
        m_layout->lines.push_back(std::move(convergence));
        return result;
    }

    std::vector<End> placeParallel(const Item& item, double axis, double y, std::vector<End> ends)
    {
        const bool opened = item.transition != 0;
        const double lineY = y + kLineMargin;
        const double top = opened ? lineY + kDoubleLineGap : y;
        if (opened) {
            GrafcetBranchLineLayout divergence;
            divergence.kind = GrafcetBranchLineLayout::Kind::SimultaneousDivergence;
            divergence.y = lineY;
            divergence.left = axis + item.branchAxis.front() - kLineOverhang;
            divergence.right = axis + item.branchAxis.back() + kLineOverhang;
            divergence.transition = item.transition;
            divergence.branches = transitionAt(transitionIndex(item.transition)).downstream;
            m_layout->lines.push_back(std::move(divergence));
        }
        const double closeY = top + item.branchHeight + kLineMargin;
        std::vector<int> closingUpstream;
        if (item.closing != 0)
            closingUpstream = transitionAt(transitionIndex(item.closing)).upstream;
        GrafcetBranchLineLayout convergence;
        convergence.kind = GrafcetBranchLineLayout::Kind::SimultaneousConvergence;
        convergence.y = closeY;
        convergence.left = axis;
        convergence.right = axis;
        convergence.transition = item.closing;
        std::vector<End> result;
        for (std::size_t b = 0; b < item.branches.size(); ++b) {
            const double branchAxis = axis + item.branchAxis[b];
            std::vector<End> into;
            if (opened) {
                for (const End& end : ends) {
                    if (end.isStep)
                        continue;
                    End copy = end;
                    extend(copy.path, {axis, lineY});
                    extend(copy.path, {branchAxis, lineY});
                    extend(copy.path, {branchAxis, top});
                    into.push_back(std::move(copy));
                }
            }
            std::vector<End> out = place(item.branches[b], branchAxis, top, std::move(into));
            if (item.closing == 0)
                continue;
            for (End& end : out) {
                if (!end.isStep || std::find(closingUpstream.begin(), closingUpstream.end(), end.number) == closingUpstream.end())
                    continue;
                const double x = end.path.back().x; // a step of a selection's branch, or the branch's own
                extend(end.path, {x, closeY});
                extend(end.path, {axis, closeY});
                extend(end.path, {axis, closeY + kDoubleLineGap});
                convergence.left = std::min(convergence.left, x);
                convergence.right = std::max(convergence.right, x);
                convergence.branches.push_back(end.number);
                result.push_back(std::move(end));
            }
        }
        if (item.closing != 0) {
            convergence.left -= kLineOverhang;
            convergence.right += kLineOverhang;
            m_layout->lines.push_back(std::move(convergence));
        }
        return result;
    }

    static Rect bounds(const GrafcetLayout& layout)
    {
        bool any = false;
        double left = 0, top = 0, right = 0, bottom = 0;
        const auto add = [&](double x0, double y0, double x1, double y1) {
            if (!any) {
                left = x0, top = y0, right = x1, bottom = y1;
                any = true;
                return;
            }
            left = std::min(left, x0);
            top = std::min(top, y0);
            right = std::max(right, x1);
            bottom = std::max(bottom, y1);
        };
        const auto addRect = [&](const Rect& r) {
            if (r.width > 0 || r.height > 0)
                add(r.left(), r.top(), r.right(), r.bottom());
        };
        for (const GrafcetStepLayout& step : layout.steps) {
            addRect(step.box);
            for (const GrafcetActionLayout& action : step.actions) {
                addRect(action.box);
                addRect(action.conditionRect);
            }
        }
        for (const GrafcetTransitionLayout& transition : layout.transitions) {
            add(transition.barCenter.x - kGrafcetBarLength / 2, transition.barCenter.y,
                transition.barCenter.x + kGrafcetBarLength / 2, transition.barCenter.y);
            addRect(transition.labelRect);
        }
        for (const GrafcetLinkLayout& link : layout.links) {
            for (const Point& p : link.route)
                add(p.x, p.y, p.x, p.y);
            addRect(link.labelRect);
            addRect(link.referenceRect);
        }
        for (const GrafcetBranchLineLayout& line : layout.lines)
            add(line.left, line.y, line.right, line.y + kDoubleLineGap);
        if (!any)
            return {0, 0, 2 * kGrafcetMargin, 2 * kGrafcetMargin};
        return Rect{left, top, right - left, bottom - top}.adjusted(kGrafcetMargin);
    }

    const Grafcet& m_grafcet;
    const TextMeasure& m_measure;
    std::map<int, int> m_stepIndex;
    std::map<int, int> m_transitionIndex;
    std::vector<bool> m_placed;
    std::vector<bool> m_drawn;
    std::vector<bool> m_detached;
    std::vector<std::vector<int>> m_outgoing;
    std::vector<Sequence> m_sequences;
    std::map<int, std::pair<int, int>> m_stepPlace; // step number -> (sequence, item)
    std::vector<std::pair<int, int>> m_backs;       // (sequence, item), in the order found
    // findJoin's scratch, by step index.
    std::vector<int> m_stamp;
    std::vector<int> m_roundOf;
    std::vector<int> m_reachCount;
    std::vector<int> m_reachSum;
    std::vector<int> m_distance;
    int m_stampValue = 0;
    int m_round = 0;
    GrafcetLayout* m_layout = nullptr;
};

} // namespace

GrafcetLayout layoutGrafcet(const Grafcet& grafcet, const TextMeasure& measure)
{
    return Builder(grafcet, measure).build();
}

} // namespace core
