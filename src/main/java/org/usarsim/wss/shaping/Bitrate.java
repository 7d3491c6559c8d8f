package org.usarsim.wss.shaping;

import org.usarsim.wss.Decimals;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Bit rates as people write them: a number of bit/s, with {@code k} for 1000 or {@code M} for
 * 1,000,000 ({@code 800}, {@code 512k}, {@code 1.5M}, {@code 54M}), read into a whole number of
 * bit/s above 0 and at most {@link #MAX}; and the time a number of bytes takes at a rate. Used by
 * {@code wss.shaping.rates} and by an operator's {@code FORCE ... {Rate 1M}}.
 */
public final class Bitrate {

    /** The largest rate accepted, 100 Gbit/s: beyond anything a robot's radio does. */
    public static final long MAX = 100_000_000_000L;

    private static final long NANOS_PER_SECOND = 1_000_000_000L;
    private static final Pattern RATE = Pattern.compile("([+-]?\\d+(?:\\.\\d+)?)([kM]?)");
    private static final String WORDS = "a number of bit/s, with k for 1000 or M for 1000000: 800, 512k, 1.5M, 54M";

    private Bitrate() {
    }

    /**
     * The rate {@code text} says, in bit/s ({@code "1.5M"} is 1,500,000); whitespace around it is
     * ignored.
     *
     * @throws IllegalArgumentException naming the text and what is wrong with it
     */
    public static long parse(String text) {
        String problem = problem(text);
        if (problem != null) {
            throw new IllegalArgumentException("\"" + text + "\" " + problem);
        }
        return value(text.strip());
    }

    /** Null when {@code text} is a rate; else what is wrong, to follow the text: "is not above 0". */
    static String problem(String text) {
        if (text == null) {
            return "is not a bit rate (" + WORDS + ")";
        }
        Matcher matcher = RATE.matcher(text.strip());
        if (!matcher.matches()) {
            return "is not a bit rate (" + WORDS + ")";
        }
        BigDecimal bits = bits(matcher);
        if (bits.signum() <= 0) {
            return "is not above 0";
        }
        if (bits.stripTrailingZeros().scale() > 0) {
            return "is not a whole number of bit/s";
        }
        if (bits.compareTo(BigDecimal.valueOf(MAX)) > 0) {
            return "is above " + toText(MAX) + ", the largest rate";
        }
        return null;
    }

    private static long value(String text) {
        Matcher matcher = RATE.matcher(text);
        matcher.matches();
        return bits(matcher).longValueExact();
    }

    private static BigDecimal bits(Matcher matcher) {
        BigDecimal number = new BigDecimal(matcher.group(1));
        return switch (matcher.group(2)) {
            case "k" -> number.scaleByPowerOfTen(3);
            case "M" -> number.scaleByPowerOfTen(6);
            default -> number;
        };
    }

    /** The rate for people: "54 Mbit/s", "1.5 Mbit/s", "512 kbit/s", "800 bit/s". */
    public static String format(long bitsPerSecond) {
        return scaled(bitsPerSecond, " Mbit/s", " kbit/s", " bit/s");
    }

    /** The rate as {@link #parse} reads it, shortest unit first: "54M", "1.5M", "512k", "800". */
    public static String toText(long bitsPerSecond) {
        return scaled(bitsPerSecond, "M", "k", "");
    }

    private static String scaled(long bitsPerSecond, String mega, String kilo, String one) {
        BigDecimal bits = BigDecimal.valueOf(bitsPerSecond);
        if (bitsPerSecond >= 1_000_000) {
            return plain(bits.scaleByPowerOfTen(-6)) + mega;
        }
        if (bitsPerSecond >= 1_000) {
            return plain(bits.scaleByPowerOfTen(-3)) + kilo;
        }
        return plain(bits) + one;
    }

    private static String plain(BigDecimal number) {
        return Decimals.plain(number);
    }

    /**
     * How long {@code bytes} take on the air at {@code bitsPerSecond}: bytes x 8 / rate, in
     * nanoseconds, rounded up (so a byte never arrives early), exact for every rate up to {@link #MAX}.
     */
    static long nanos(long bytes, long bitsPerSecond) {
        long bits = Math.multiplyExact(bytes, 8);
        long seconds = bits / bitsPerSecond;
        long rest = bits % bitsPerSecond;
        long restNanos;
        if (rest <= Long.MAX_VALUE / NANOS_PER_SECOND) {
            long scaled = rest * NANOS_PER_SECOND;
            restNanos = scaled / bitsPerSecond + (scaled % bitsPerSecond == 0 ? 0 : 1);
        } else {
            BigInteger[] division = BigInteger.valueOf(rest).multiply(BigInteger.valueOf(NANOS_PER_SECOND))
                    .divideAndRemainder(BigInteger.valueOf(bitsPerSecond));
            restNanos = division[0].longValueExact() + (division[1].signum() == 0 ? 0 : 1);
        }
        return Math.addExact(Math.multiplyExact(seconds, NANOS_PER_SECOND), restNanos);
    }

    /** How many whole bytes {@code nanos} of airtime carry at {@code bitsPerSecond}: rate x time / 8, rounded down. */
    static long bytesIn(long nanos, long bitsPerSecond) {
        long bitNanos = bitsPerSecond * nanos;
        if (Math.multiplyHigh(bitsPerSecond, nanos) == 0 && bitNanos >= 0) {
            return bitNanos / (8 * NANOS_PER_SECOND);
        }
        return BigInteger.valueOf(bitsPerSecond).multiply(BigInteger.valueOf(nanos))
                .divide(BigInteger.valueOf(8 * NANOS_PER_SECOND)).longValueExact();
    }
}
