package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.util.function.BooleanSupplier;

/**
 * The one rule for running out of descriptors (docs/architecture.md, "Decisions"): when a bind,
 * an accept or a connect fails with "Too many open files", the hub gives back remembered ports of
 * robots that left ({@code giveBack}), and the work is tried once more.
 */
public final class Descriptors {

    /** Socket work that may fail for want of a descriptor. */
    public interface Work<T> {
        T run() throws IOException;
    }

    private final BooleanSupplier giveBack;

    /** @param giveBack gives back remembered ports; true when some were (never called under the hub's lock) */
    public Descriptors(BooleanSupplier giveBack) {
        this.giveBack = giveBack;
    }

    /** EMFILE ("Too many open files") or ENFILE ("Too many open files in system"), as the JDK words them. */
    public static boolean ranOut(IOException e) {
        String message = e.getMessage();
        return message != null && message.contains("Too many open files");
    }

    /** Does the work; out of descriptors, gives some back and does it once more. */
    public <T> T retrying(Work<T> work) throws IOException {
        return retrying(work, giveBack);
    }

    /**
     * As {@link #retrying(Work)}, with the give-back named by the caller: the hub's socket work
     * after a step, handed the hub's steps with the step (docs/architecture.md, "The hub").
     */
    public static <T> T retrying(Work<T> work, BooleanSupplier giveBack) throws IOException {
        try {
            return work.run();
        } catch (IOException e) {
            if (ranOut(e) && giveBack.getAsBoolean()) {
                return work.run();
            }
            throw e;
        }
    }

    /**
     * For work that is tried again by its own loop (an accept): whether the failure was for want
     * of descriptors and some were given back.
     */
    public boolean gaveBack(IOException failure) {
        return ranOut(failure) && giveBack.getAsBoolean();
    }
}
