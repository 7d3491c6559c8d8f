package org.usarsim.wss.bench;

/** A check's verdicts, one line each ({@code PASS} or {@code FAIL}, what was checked, its figures), and whether all passed. */
final class Verdicts {

    private int passed;
    private int failed;

    /** Says one verdict; gives it back. */
    boolean say(String check, boolean pass, String figures) {
        if (pass) {
            passed++;
        } else {
            failed++;
        }
        System.out.println((pass ? "PASS  " : "FAIL  ") + check + ": " + figures);
        return pass;
    }

    /** A check that could not be made (the scenario broke off): a failure. */
    void broke(String scenario, Exception e) {
        say(scenario, false, "broke off: " + e);
    }

    boolean allPassed() {
        return failed == 0 && passed > 0;
    }

    String summary() {
        return passed + " passed, " + failed + " failed";
    }
}
