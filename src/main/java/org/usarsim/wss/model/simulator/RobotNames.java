package org.usarsim.wss.model.simulator;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * WSS robot names to the names a ROS source gives the robots (models, frames, topics), and back
 * ({@code rosbridge.names}): {@code Scout=scout_1,Operator=op}; every robot not listed by the
 * pattern, {@code {robot}} (its WSS name) by default and {@code {robot}/base_link} on {@code /tf};
 * an entry {@code {robot}=...} sets the pattern.
 */
final class RobotNames {

    static final String ROBOT = "{robot}";

    private final Map<String, String> toModel;
    private final Map<String, String> toWss = new LinkedHashMap<>();
    private final String pattern;
    private final String prefix;
    private final String suffix;

    private RobotNames(Map<String, String> toModel, String pattern) {
        this.toModel = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(toModel));
        this.pattern = pattern;
        int at = pattern.indexOf(ROBOT);
        prefix = pattern.substring(0, at);
        suffix = pattern.substring(at + ROBOT.length());
        toModel.forEach((wss, model) -> toWss.put(model, wss));
    }

    /**
     * The names of {@code text} ({@code WSS=MODEL} separated by commas; empty: none), each robot not
     * listed by {@code pattern} unless the text sets its own.
     *
     * @throws IllegalArgumentException naming what is wrong: an entry without {@code =}, an empty
     *                                  name, a robot or a model named twice, a pattern without {@code {robot}}
     */
    static RobotNames parse(String text, String pattern) {
        Map<String, String> names = new LinkedHashMap<>();
        String own = pattern;
        if (!text.isBlank()) {
            for (String entry : text.split(",", -1)) {
                int equals = entry.indexOf('=');
                String wss = equals < 0 ? "" : entry.substring(0, equals).strip();
                String model = equals < 0 ? "" : entry.substring(equals + 1).strip();
                if (wss.isEmpty() || model.isEmpty()) {
                    throw new IllegalArgumentException("'" + entry.strip() + "' is not WSS=MODEL");
                }
                if (wss.equals(ROBOT)) {
                    if (!model.contains(ROBOT)) {
                        throw new IllegalArgumentException("the pattern '" + model + "' does not hold " + ROBOT);
                    }
                    own = model;
                } else if (names.containsKey(wss)) {
                    throw new IllegalArgumentException(wss + " is named twice");
                } else if (names.containsValue(model)) {
                    throw new IllegalArgumentException("two robots are " + model);
                } else {
                    names.put(wss, model);
                }
            }
        }
        return new RobotNames(names, own);
    }

    /** The source's name of a WSS robot. */
    String model(String wss) {
        String listed = toModel.get(wss);
        return listed != null ? listed : pattern.replace(ROBOT, wss);
    }

    /**
     * The WSS robot a source's name stands for, or null when it stands for none: neither listed nor
     * of the pattern's form, or of the form of a robot listed under another name.
     */
    String wss(String model) {
        String listed = toWss.get(model);
        if (listed != null) {
            return listed;
        }
        if (model.length() <= prefix.length() + suffix.length() || !model.startsWith(prefix) || !model.endsWith(suffix)) {
            return null;
        }
        String wss = model.substring(prefix.length(), model.length() - suffix.length());
        return toModel.containsKey(wss) ? null : wss;
    }

    /** The robots listed by name (WSS to source), in the order given. */
    Map<String, String> listed() {
        return toModel;
    }

    @Override
    public String toString() {
        StringBuilder text = new StringBuilder();
        toModel.forEach((wss, model) -> text.append(wss).append('=').append(model).append(", "));
        return text.append("others ").append(pattern).toString();
    }
}
