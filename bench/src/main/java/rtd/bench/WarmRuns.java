package rtd.bench;

import java.util.Arrays;
import rtd.cli.RtdCommand;

/**
 * Runs rtd's command several times in one JVM, so that a run whose code the JIT has already
 * compiled can be set beside the first one, as {@code java -jar rtd.jar} runs it: how much of a
 * run is the JIT's. Pass {@code --stats} to see each run's phases.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar rtd.bench.WarmRuns 4 bench/scenes/shaded_100000.txt -o /tmp/s.png --stats
 * </pre>
 *
 * The first argument is the number of runs; the others are rtd's.
 */
public final class WarmRuns {

    private WarmRuns() {
    }

    public static void main(String[] args) {
        if (args.length < 2) {
            System.err.println("usage: WarmRuns RUNS SCENE [rtd's options]");
            System.exit(2);
        }
        int runs = Integer.parseInt(args[0]);
        String[] command = Arrays.copyOfRange(args, 1, args.length);
        for (int run = 1; run <= runs; run++) {
            System.err.println("run " + run + (run == 1 ? " (cold, as java -jar runs it)" : " (warm)"));
            int exit = RtdCommand.commandLine().execute(command);
            if (exit != 0) {
                System.exit(exit);
            }
        }
    }
}
