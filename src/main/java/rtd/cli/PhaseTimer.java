package rtd.cli;

import java.util.LinkedHashMap;
import java.util.Map;

/** Measures the wall time of each phase of a run, one after the other. */
final class PhaseTimer {

    private final Map<String, Long> nanos = new LinkedHashMap<>();
    private long phaseStart = System.nanoTime();

    /** Ends the running phase under {@code name} and starts the next. */
    void endPhase(String name) {
        long now = System.nanoTime();
        nanos.put(name, now - phaseStart);
        phaseStart = now;
    }

    /** Each phase's time in seconds, in the order they ran. */
    Map<String, Double> seconds() {
        Map<String, Double> result = new LinkedHashMap<>();
        nanos.forEach((name, time) -> result.put(name, time / 1e9));
        return result;
    }
}
