package rtd.cli;

/**
 * The options that shape every scene's run, as the command line gave them.
 *
 * @param width    image width after {@code --scale}
 * @param height   image height after {@code --scale}
 * @param scale    the {@code --scale} factor, applied to the camera
 * @param threads  threads to render and build with
 * @param accel    {@code --accel}
 * @param paper    {@code --paper}: the paper's own code
 * @param samples  {@code --samples}: N × N rays per pixel
 * @param stats    {@code --stats}
 * @param progress whether to show the progress line (on a terminal, without {@code --no-progress})
 */
record Settings(int width, int height, Scale scale, int threads, Accel accel, boolean paper, int samples, boolean stats,
        boolean progress) {
}
