// The file dialogs (file_dialogs.h): one remembered folder for all of them.
#include "file_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>

namespace raystep::gui {

namespace {
constexpr auto kFolderKey = "dialogs/folder";

QString remembered(const QString& path) {
    if (!path.isEmpty()) QSettings().setValue(kFolderKey, QFileInfo(path).absolutePath());
    return path;
}
}  // namespace

QString lastDialogFolder() {
    const QString folder = QSettings().value(kFolderKey).toString();
    // A folder since removed (a USB stick taken out): the working directory, as at first.
    return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QDir::currentPath();
}

QString openFileName(QWidget* parent, const QString& caption, const QString& filter,
                     QString* selectedFilter) {
    return remembered(
        QFileDialog::getOpenFileName(parent, caption, lastDialogFolder(), filter, selectedFilter));
}

QString saveFileName(QWidget* parent, const QString& caption, const QString& filter,
                     QString* selectedFilter, const QString& suggested) {
    const QString start =
        suggested.isEmpty() ? lastDialogFolder() : QDir(lastDialogFolder()).filePath(suggested);
    return remembered(QFileDialog::getSaveFileName(parent, caption, start, filter, selectedFilter));
}

}  // namespace raystep::gui
