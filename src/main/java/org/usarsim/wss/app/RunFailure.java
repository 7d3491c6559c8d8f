package org.usarsim.wss.app;

/** Why a run ends before it serves: the exit code ({@link Main#BAD_INPUT}, {@link Main#CANNOT_START}) and the one line for standard error. */
final class RunFailure extends Exception {

    final int code;

    RunFailure(int code, String message) {
        super(message);
        this.code = code;
    }

    /** Bad input: a command line, a file or a value the run refuses before anything listens. */
    static RunFailure badInput(String message) {
        return new RunFailure(Main.BAD_INPUT, message);
    }
}
