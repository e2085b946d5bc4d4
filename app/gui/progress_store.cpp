#include "progress_store.h"

#include "course/lesson.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QObject>
#include <QSaveFile>

#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace raystep::gui {

namespace {

/// Why nothing can be written in `folder`, from the folder itself: permission, a full disk.
QString folderProblem(const QString& folder) {
    const QByteArray f = QFile::encodeName(folder);
    if (::access(f.constData(), W_OK) != 0)
        return QObject::tr("permission denied: the folder %1 is not writable").arg(folder);
    struct statvfs fs {};
    if (::statvfs(f.constData(), &fs) == 0 && fs.f_bavail == 0)
        return QObject::tr("the disk is full (%1)").arg(folder);
    return {};
}

}  // namespace

QString ProgressStore::keepAside(const QString& path, QString& why) {
    // The first free number: an earlier file kept aside is never replaced (QFile::rename would
    // not replace it anyway, and used to fail in silence).
    for (int n = 1; n < 10000; ++n) {
        const QString aside = QStringLiteral("%1.unreadable-%2").arg(path).arg(n);
        if (QFileInfo::exists(aside) || QFileInfo(aside).isSymLink()) continue;
        QFile file(path);
        if (file.rename(aside)) return aside;
        why = file.errorString();
        if (const QString folder = folderProblem(QFileInfo(path).absolutePath()); !folder.isEmpty())
            why = folder;
        return {};
    }
    why = QObject::tr("%1.unreadable-1 to -9999 are all taken").arg(path);
    return {};
}

Progress ProgressStore::open(Unreadable& unreadable) {
    unreadable = {};
    try {
        if (auto saved = loadProgressFile(path_.toStdString())) return std::move(*saved);
    } catch (const LessonError& e) {
        unreadable.why = QString::fromUtf8(e.what());
        unreadable.keptAs = keepAside(path_, unreadable.moveProblem);
        blocked_ = unreadable.keptAs.isEmpty();
    }
    return {};
}

QString ProgressStore::save(Progress& progress, Unreadable& unreadable) {
    unreadable = {};
    const QString folder = QFileInfo(path_).absolutePath();
    if (!QDir().mkpath(folder)) {
        const QString why = folderProblem(QFileInfo(folder).absolutePath());
        return why.isEmpty() ? QObject::tr("the folder %1 cannot be made").arg(folder) : why;
    }
    // Another window of the app may have saved since: its answers are folded in under a lock.
    QLockFile lock(path_ + ".lock");
    if (!lock.tryLock(2000)) {
        switch (lock.error()) {
            case QLockFile::LockFailedError:
                return QObject::tr("another raystep window holds the lock %1").arg(path_ + ".lock");
            case QLockFile::PermissionError:
                return QObject::tr("permission denied: the folder %1 is not writable").arg(folder);
            default: {
                const QString why = folderProblem(folder);
                return why.isEmpty()
                           ? QObject::tr("the lock file %1 cannot be made").arg(path_ + ".lock")
                           : why;
            }
        }
    }
    if (blocked_) {
        // The unreadable file is still there: moved aside now if it can be, else left alone.
        if (QFileInfo::exists(path_)) {
            QString why;
            if (keepAside(path_, why).isEmpty())
                return QObject::tr(
                           "%1 could not be read and cannot be moved aside (%2); it is "
                           "not written over")
                    .arg(path_, why);
        }
        blocked_ = false;
    }
    try {
        if (const auto saved = loadProgressFile(path_.toStdString()))
            mergeProgress(progress, *saved);
    } catch (const LessonError& e) {
        // Unreadable now (another window, or a hand, changed it): kept aside, not replaced.
        unreadable.why = QString::fromUtf8(e.what());
        unreadable.keptAs = keepAside(path_, unreadable.moveProblem);
        if (unreadable.keptAs.isEmpty()) {
            blocked_ = true;
            return QObject::tr(
                       "%1 could not be read and cannot be moved aside (%2); it is not "
                       "written over")
                .arg(path_, unreadable.moveProblem);
        }
    }
    QSaveFile f(path_);
    const QByteArray bytes = QByteArray::fromStdString(progressToJson(progress));
    if (f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size() && f.commit()) return {};
    // In words: what the file system said, the folder's state when that says more.
    switch (f.error()) {
        case QFileDevice::ResourceError:
            return QObject::tr("the disk is full (%1)").arg(folder);
        case QFileDevice::PermissionsError:
            return QObject::tr("permission denied: %1 or its folder is not writable").arg(path_);
        default: {
            const QString why = folderProblem(folder);
            return why.isEmpty() ? path_ + QStringLiteral(": ") + f.errorString() : why;
        }
    }
}

}  // namespace raystep::gui
