#pragma once
// Who a lesson is run for: the panel, its exercise box and the main window's menus share it.

namespace raystep::gui {

/// Who a lesson is run for. Quiz: a student answers; every unsolved exercise holds the replay at
/// its position and the prompts after it. Presenting: a lecturer in front of the room; every
/// step and view is free, the exercises are questions to the room, an answer is shown only when
/// the lecturer reveals that one. Lecturer: preparing; every answer is shown.
enum class LessonMode { Quiz, Presenting, Lecturer };

}  // namespace raystep::gui
