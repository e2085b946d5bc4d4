#pragma once
// The app's file dialogs: each opens in the folder the last file was chosen in, by whichever
// dialog (QSettings "dialogs/folder"; the working directory at first), and remembers the folder
// of the file chosen. A lecturer who saves screenshots, boards and traces into one folder does
// not walk back to it from the working directory every time.
#include <QString>

class QWidget;

namespace raystep::gui {

/// The folder the next dialog opens in.
QString lastDialogFolder();
/// QFileDialog::getOpenFileName, from lastDialogFolder(); the chosen file's folder remembered.
QString openFileName(QWidget* parent, const QString& caption, const QString& filter,
                     QString* selectedFilter = nullptr);
/// QFileDialog::getSaveFileName, from lastDialogFolder() (with `suggested` as the file's name,
/// if any); the chosen file's folder remembered.
QString saveFileName(QWidget* parent, const QString& caption, const QString& filter,
                     QString* selectedFilter = nullptr, const QString& suggested = {});

}  // namespace raystep::gui
