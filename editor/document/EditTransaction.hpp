#pragma once

#include <QString>
#include <memory>

class QUndoCommand;
class QUndoStack;

namespace speculum::document {

class TransactionStep;

// One edit of the document as one undo step, all or nothing. Commands pushed into the transaction run at
// once (so each one sees the scene as the ones before it left it), but reach the undo stack only at
// commit(), together, as a single step with the transaction's label. A transaction destroyed without
// commit() (an early return, an exception) undoes what it ran, in reverse order, and leaves the stack as it
// found it: no step, the redo history kept, the clean state unchanged. commit() with nothing pushed leaves
// no step either, so an edit that turns out to change nothing is never an undo step.
//
//     EditTransaction edit(undo, QStringLiteral("Delete 2 nodes"));
//     for (NodeId id : roots) edit.push(new RemoveNodeCommand(scene, id));
//     edit.commit();
class EditTransaction {
public:
    // An empty label reads like the transaction's command when it holds exactly one ("Delete “Box”").
    explicit EditTransaction(QUndoStack& stack, QString label = {});
    ~EditTransaction();
    EditTransaction(const EditTransaction&) = delete;
    EditTransaction& operator=(const EditTransaction&) = delete;

    // Runs command->redo() and keeps it (the transaction owns it). As on a QUndoStack, a command that is
    // obsolete after its redo() is dropped, and one that merges into the previous command is deleted:
    // read what you need from it (an added node's id) before the next push.
    void push(QUndoCommand* command);
    // Commands kept so far.
    int size() const;
    bool empty() const { return size() == 0; }

    // Hands the commands to the stack as one step (none: no step). Pushing after commit() is a programmer
    // error.
    void commit();

private:
    QUndoStack& m_stack;
    std::unique_ptr<TransactionStep> m_step; // null after commit()
};

} // namespace speculum::document
