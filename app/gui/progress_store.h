#pragma once
// The student's progress file (the user's data folder, progress.json): read once at start,
// saved after every answer. A file that cannot be read (broken, from a newer raystep, not
// readable) is never written over: it is moved aside under a name no earlier one holds
// (progress.json.unreadable-1, -2, ...), and if even that fails nothing is written there. A save
// folds in what another window saved (under a lock), writes beside and renames (QSaveFile: a
// full disk or a kill leaves the old file whole), and says why it failed in words.
#include "course/progress.h"

#include <QString>

namespace raystep::gui {

class ProgressStore {
  public:
    explicit ProgressStore(QString path) : path_(std::move(path)) {}
    const QString& path() const { return path_; }

    /// What reading or saving found wrong with the file on disk.
    struct Unreadable {
        QString why;          // why it could not be read ("" when it could)
        QString keptAs;       // where it was moved ("" when the move failed: then it stays and is
                              // not written over)
        QString moveProblem;  // why the move failed
    };

    /// The saved progress (empty when there is none, or none readable); `unreadable` says what
    /// was wrong with the file, if anything.
    Progress open(Unreadable& unreadable);

    /// Saves `progress` (folding in what another window saved since). "" when saved, else why
    /// not, in words: permission, a full disk, another window holding the lock. `progress` keeps
    /// every answer either way. A file found unreadable now is moved aside first (`unreadable`).
    QString save(Progress& progress, Unreadable& unreadable);

    /// Moves `path` to path.unreadable-N, N the first number no file has; the new name, or ""
    /// when the move failed (`why` says why).
    static QString keepAside(const QString& path, QString& why);

  private:
    QString path_;
    bool blocked_ = false;  // an unreadable file could not be moved: it is left, never replaced
};

}  // namespace raystep::gui
