package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** Bit rates as people write them, and the time bytes take at a rate. */
class BitrateTest {

    private static final String WORDS = "is not a bit rate (a number of bit/s, with k for 1000 or M for 1000000: 800, 512k, 1.5M, 54M)";

    @Test
    void readsBitsKilobitsAndMegabits() {
        assertEquals(54_000_000, Bitrate.parse("54M"));
        assertEquals(512_000, Bitrate.parse("512k"));
        assertEquals(1000, Bitrate.parse("1000"));
        assertEquals(1_500_000, Bitrate.parse("1.5M"));
        assertEquals(500, Bitrate.parse("0.5k"));
        assertEquals(6_000_000, Bitrate.parse(" 6M "), "whitespace around it is ignored");
        assertEquals(Bitrate.MAX, Bitrate.parse("100000M"));
    }

    @Test
    void refusesWhatIsNotARateNamingTheText() {
        assertRefused("fast", "\"fast\" " + WORDS);
        assertRefused("", "\"\" " + WORDS);
        assertRefused("54m", "\"54m\" " + WORDS);
        assertRefused("54 M", "\"54 M\" " + WORDS);
        assertRefused("1e6", "\"1e6\" " + WORDS);
        assertRefused("54Mbit/s", "\"54Mbit/s\" " + WORDS);
        assertRefused(null, "\"null\" " + WORDS);
        assertRefused("0", "\"0\" is not above 0");
        assertRefused("0.0M", "\"0.0M\" is not above 0");
        assertRefused("-5M", "\"-5M\" is not above 0");
        assertRefused("1.5", "\"1.5\" is not a whole number of bit/s");
        assertRefused("1.0005k", "\"1.0005k\" is not a whole number of bit/s");
        assertRefused("100000.001M", "\"100000.001M\" is above 100000M, the largest rate");
        assertRefused("99999999999999999999999", "\"99999999999999999999999\" is above 100000M, the largest rate");
    }

    private static void assertRefused(String text, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> Bitrate.parse(text)).getMessage());
    }

    @Test
    void saysARateForPeople() {
        assertEquals("54 Mbit/s", Bitrate.format(54_000_000));
        assertEquals("1.5 Mbit/s", Bitrate.format(1_500_000));
        assertEquals("512 kbit/s", Bitrate.format(512_000));
        assertEquals("1.234 kbit/s", Bitrate.format(1_234));
        assertEquals("800 bit/s", Bitrate.format(800));
        assertEquals("100000 Mbit/s", Bitrate.format(Bitrate.MAX));
    }

    @Test
    void writesARateAsItIsReadBack() {
        assertEquals("54M", Bitrate.toText(54_000_000));
        assertEquals("512k", Bitrate.toText(512_000));
        assertEquals("800", Bitrate.toText(800));
        for (long rate : new long[] {1, 999, 1000, 1001, 1_500_000, 11_000_000, 123_456_789, Bitrate.MAX}) {
            assertEquals(rate, Bitrate.parse(Bitrate.toText(rate)), Bitrate.toText(rate));
        }
    }

    @Test
    void bytesTakeTheirBitsOverTheRateRoundedUp() {
        assertEquals(512_000, Bitrate.nanos(64, 1_000_000), "64 bytes at 1 Mbit/s: 512 us");
        assertEquals(2_000_000, Bitrate.nanos(13_500, 54_000_000));
        assertEquals(2_666_666_667L, Bitrate.nanos(1, 3), "8/3 s, rounded up");
        assertEquals(0, Bitrate.nanos(0, 1));
        assertEquals(1_000_000_000, Bitrate.nanos(12_500_000_000L, Bitrate.MAX), "12.5 GB at 100 Gbit/s");
        assertEquals(1_000_000_000, Bitrate.nanos(12_499_999_999L, Bitrate.MAX), "just under a second, rounded up");
        assertEquals(13_500, Bitrate.bytesIn(2_000_000, 54_000_000));
        assertEquals(0, Bitrate.bytesIn(2_000_000, 3_999), "2 ms at 3999 bit/s is not a whole byte");
        assertEquals(125_000_000_000L, Bitrate.bytesIn(10_000_000_000L, Bitrate.MAX), "beyond a long's product: exact");
    }
}
