// Gestures (DESIGN.md, "The document"): one brush stroke, slider drag or burst of wheel ticks is
// one undo step. A Gesture is a token the caller holds for the length of the gesture and hands to
// each edit that should merge; an edit given no gesture is an undo step of its own. Nothing in the
// document remembers an "open" gesture, so two controls, a tool and a panel, can never merge into
// each other's steps by accident.
#pragma once

#include <utility>

namespace celform::model {

/// Names one gesture for the edits made in it; the default names none.
struct GestureId {
    int value = 0;

    [[nodiscard]] explicit operator bool() const { return value != 0; }
    friend bool operator==(GestureId a, GestureId b) { return a.value == b.value; }
    friend bool operator!=(GestureId a, GestureId b) { return a.value != b.value; }
};

/// An open gesture, made by Document::beginGesture(); it ends when destroyed or by end(). Edits
/// that take it (as a GestureId) merge with the previous edit of the same property on the same
/// target made in the same gesture. Move-only, so that one gesture has one owner.
class Gesture {
public:
    Gesture() = default; ///< no gesture: edits given it are one step each
    ~Gesture() = default;
    Gesture(Gesture&& other) noexcept
        : m_id(std::exchange(other.m_id, GestureId{}))
    { }
    Gesture& operator=(Gesture&& other) noexcept
    {
        m_id = std::exchange(other.m_id, GestureId{});
        return *this;
    }
    Gesture(const Gesture&) = delete;
    Gesture& operator=(const Gesture&) = delete;

    /// Ends the gesture: later edits never merge into the steps made in it.
    void end() { m_id = {}; }
    [[nodiscard]] bool isOpen() const { return bool(m_id); }
    [[nodiscard]] GestureId id() const { return m_id; }
    // NOLINTNEXTLINE(google-explicit-constructor): passing the gesture itself reads best
    operator GestureId() const { return m_id; }

private:
    friend class Document;
    explicit Gesture(int id)
        : m_id{id}
    { }

    GestureId m_id;
};

} // namespace celform::model
