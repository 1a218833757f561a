package rtd.cli;

import picocli.CommandLine.IVersionProvider;

/** {@code --version}: the version that Maven wrote into the jar's manifest. */
final class VersionProvider implements IVersionProvider {

    @Override
    public String[] getVersion() {
        String version = RtdCommand.class.getPackage().getImplementationVersion();
        return new String[] {"rtd " + (version != null ? version : "(development build, not from the jar)"),
            "Java " + System.getProperty("java.version")};
    }
}
