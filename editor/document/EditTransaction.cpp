#include "editor/document/EditTransaction.hpp"

#include <QUndoCommand>
#include <QUndoStack>
#include <cassert>
#include <utility>
#include <vector>

namespace speculum::document {

// The undo step a committed transaction leaves: its commands, undone in reverse and redone in order. Its
// commands have run already when the stack pushes it, so the push's redo() does nothing.
class TransactionStep : public QUndoCommand {
public:
    explicit TransactionStep(const QString& label)
        : QUndoCommand(label) {}

    void redo() override {
        if (m_applied) {
            m_applied = false;
            return;
        }
        for (auto& command : m_commands) {
            command->redo();
        }
    }
    void undo() override {
        for (auto it = m_commands.rbegin(); it != m_commands.rend(); ++it) {
            (*it)->undo();
        }
    }

    void add(QUndoCommand* raw) {
        std::unique_ptr<QUndoCommand> command(raw);
        command->redo();
        if (command->isObsolete()) {
            return; // changed nothing
        }
        if (!m_commands.empty()) {
            QUndoCommand& last = *m_commands.back();
            if (last.id() != -1 && last.id() == command->id() && last.mergeWith(command.get())) {
                if (last.isObsolete()) { // the merge cancelled out: the pair changed nothing
                    last.undo();
                    m_commands.pop_back();
                }
                return;
            }
        }
        m_commands.push_back(std::move(command));
    }

    // Rolls back what ran: the scene is as it was before the first push.
    void undoAll() {
        undo();
        m_commands.clear();
    }

    int size() const { return static_cast<int>(m_commands.size()); }
    const QUndoCommand& only() const { return *m_commands.front(); }

private:
    std::vector<std::unique_ptr<QUndoCommand>> m_commands;
    bool m_applied = true;
};

EditTransaction::EditTransaction(QUndoStack& stack, QString label)
    : m_stack(stack)
    , m_step(std::make_unique<TransactionStep>(std::move(label))) {}

EditTransaction::~EditTransaction() {
    if (m_step) {
        m_step->undoAll();
    }
}

void EditTransaction::push(QUndoCommand* command) {
    assert(m_step && "EditTransaction::push(): the transaction was committed");
    assert(command && "EditTransaction::push(): no command");
    m_step->add(command);
}

int EditTransaction::size() const {
    return m_step ? m_step->size() : 0;
}

void EditTransaction::commit() {
    assert(m_step && "EditTransaction::commit(): committed twice");
    std::unique_ptr<TransactionStep> step = std::move(m_step);
    if (step->size() == 0) {
        return;
    }
    if (step->text().isEmpty() && step->size() == 1) {
        step->setText(step->only().text());
    }
    m_stack.push(step.release()); // its redo() finds the commands applied
}

} // namespace speculum::document
