package org.usarsim.wss.ros;

/**
 * How much JSON {@link Json#parse} takes: the text's length in chars (a UTF-16 {@code String}'s
 * length, never more than its UTF-8 bytes) and the nesting of arrays and objects.
 *
 * @param maxChars the longest text, in chars; a longer one is refused before it is read
 * @param maxDepth the deepest nesting of arrays and objects, 1 to 1000; {@code []} is depth 1
 */
public record JsonLimits(int maxChars, int maxDepth) {

    /** 16 MiB: a 2000 x 2000 occupancy grid written as rosbridge writes it fits. */
    public static final int DEFAULT_MAX_CHARS = 16 * 1024 * 1024;
    /** 64: the deepest ROS message a position source reads is 7 (msg.transforms[i].transform.rotation). */
    public static final int DEFAULT_MAX_DEPTH = 64;
    /** The defaults: 16 MiB, 64 levels. */
    public static final JsonLimits DEFAULT = new JsonLimits(DEFAULT_MAX_CHARS, DEFAULT_MAX_DEPTH);

    public JsonLimits {
        if (maxChars < 1 || maxDepth < 1 || maxDepth > Json.DEPTH_CEILING) {
            throw new IllegalArgumentException("JSON limits: chars from 1 on, depth 1 to " + Json.DEPTH_CEILING + ", not "
                    + maxChars + " chars, depth " + maxDepth);
        }
    }

    /** These limits with another text size. */
    public JsonLimits withMaxChars(int chars) {
        return new JsonLimits(chars, maxDepth);
    }
}
