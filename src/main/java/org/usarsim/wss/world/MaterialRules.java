package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Which material a wall of a Gazebo world is made of, from its names: rules {@code GLOB=MATERIAL}
 * separated by commas ({@code Hard_wall*=concrete, *glass*=glass, *=concrete}), tried in order on
 * the names of the box's models (outermost first), its link and its collision; the first rule
 * whose glob matches one of them wins. A glob's {@code *} is any run of characters, {@code ?} one
 * character; case does not matter. No rule matching: no material (the model's attenuation).
 * Immutable.
 */
public final class MaterialRules {

    /** A material's name: letters, digits, {@code _} and {@code -}. */
    static final Pattern MATERIAL = Pattern.compile("[A-Za-z0-9_-]+");

    private record Rule(String glob, Pattern pattern, String material) {
    }

    public static final MaterialRules NONE = new MaterialRules(List.of());

    private final List<Rule> rules;

    private MaterialRules(List<Rule> rules) {
        this.rules = List.copyOf(rules);
    }

    /** The rules of this text; empty text: none. */
    public static MaterialRules parse(String text) {
        List<Rule> rules = new ArrayList<>();
        if (text.isBlank()) {
            return NONE;
        }
        for (String part : text.split(",", -1)) {
            String rule = part.strip();
            int equals = rule.lastIndexOf('=');
            String glob = equals < 0 ? "" : rule.substring(0, equals).strip();
            String material = equals < 0 ? "" : rule.substring(equals + 1).strip();
            if (glob.isEmpty() || !MATERIAL.matcher(material).matches()) {
                throw new IllegalArgumentException("'" + rule + "' is not GLOB=MATERIAL (a material is letters, digits, _ and -)");
            }
            rules.add(new Rule(glob, glob(glob), material.toLowerCase(Locale.ROOT)));
        }
        return new MaterialRules(rules);
    }

    private static Pattern glob(String glob) {
        StringBuilder regex = new StringBuilder();
        StringBuilder literal = new StringBuilder();
        for (char c : glob.toCharArray()) {
            if (c == '*' || c == '?') {
                regex.append(Pattern.quote(literal.toString())).append(c == '*' ? ".*" : ".");
                literal.setLength(0);
            } else {
                literal.append(c);
            }
        }
        regex.append(Pattern.quote(literal.toString()));
        return Pattern.compile(regex.toString(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE | Pattern.DOTALL);
    }

    /** The material of the first rule matching one of these names; empty when none does. */
    public String materialOf(List<String> names) {
        for (Rule rule : rules) {
            for (String name : names) {
                if (rule.pattern().matcher(name).matches()) {
                    return rule.material();
                }
            }
        }
        return "";
    }

    /** The materials the rules name, in their order, each once. */
    public List<String> materials() {
        return rules.stream().map(Rule::material).distinct().toList();
    }
}
