#pragma once
// What a user can see of an undo stack: its steps, where it stands, and where the saved state is.
#include <QUndoStack>

namespace speculum::document::test {

struct UndoStackState {
    int count = 0;
    int index = 0;
    int cleanIndex = 0;
    bool clean = false;
    bool operator==(const UndoStackState&) const = default;
};

inline UndoStackState undoStackState(const QUndoStack& stack) {
    return {stack.count(), stack.index(), stack.cleanIndex(), stack.isClean()};
}

} // namespace speculum::document::test
