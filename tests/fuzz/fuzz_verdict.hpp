// What a fuzz target concluded about its last input, for the corpus replay
// (replay_main.cpp): a target sets `accepted` when the input parsed -- or, for the
// generator, when its law emitted code -- so that the replay can check that a seed which
// must parse (a VTK-written .vtu, a real checkpoint, a documented scene) still does, and
// that a seed kept because it must be refused still is. Without this a reader that began
// refusing every valid file would pass the replay: refusing cleanly is allowed.
#pragma once

namespace pdfuzz {
inline bool accepted = false;
}  // namespace pdfuzz
