/**
 * The command line ({@code java -jar rtd.jar}): options, where each picture goes, the phases of a run and their
 * times, and messages for people with exit codes 0, 1 and 2. The top layer: nothing else of rtd depends on it.
 */
package rtd.cli;
