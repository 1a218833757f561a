package rtd.cli;

import rtd.io.ImageFormat;

/**
 * A scene with where its picture goes, or why it cannot go there (a file error, reported in its
 * turn): what {@link JobPlanner} makes of each scene on the command line before any rendering,
 * and what {@link RtdCommand} then runs, one after another.
 */
record Job(SceneSource source, OutputTarget target, ImageFormat format, FileError refusal) {
}
