package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link Strengths#format} against C's {@code printf("%g")}. Every expected string below was
 * produced by glibc's printf (gcc, x86-64) for the same double and is written here literally.
 */
class StrengthsTest {

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(delimiter = '|', textBlock = """
            0.0               | 0
            -0.0              | -0
            -100              | -100
            -49.67            | -49.67
            -67.1235          | -67.1235
            -56.6597          | -56.6597
            -1234567.0        | -1.23457e+06
            1234567.0         | 1.23457e+06
            123456.0          | 123456
            600000            | 600000
            100000            | 100000
            1000000           | 1e+06
            1.0               | 1
            -1.5              | -1.5
            -0.5              | -0.5
            2.5               | 2.5
            8.5               | 8.5
            0.1               | 0.1
            0.15              | 0.15
            0.25              | 0.25
            0.3               | 0.3
            1234.5            | 1234.5
            -93               | -93
            -7.25e-3          | -0.00725
            0.001             | 0.001
            0.01              | 0.01
            """)
    void plainValues(String input, String expected) {
        assertEquals(expected, Strengths.format(Double.parseDouble(input)));
    }

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(delimiter = '|', textBlock = """
            0.0001            | 0.0001
            0.00001           | 1e-05
            -0.00001          | -1e-05
            1.5e-5            | 1.5e-05
            0.000123456789    | 0.000123457
            -0.000999999      | -0.000999999
            0.0000999999      | 9.99999e-05
            0.00009999949     | 9.99995e-05
            0.000099999995    | 0.0001
            0.00009999995     | 0.0001
            0.00001234565     | 1.23456e-05
            -1e-7             | -1e-07
            -2.5e-9           | -2.5e-09
            1e-10             | 1e-10
            """)
    void smallValuesSwitchToExponentBelowMinusFour(String input, String expected) {
        assertEquals(expected, Strengths.format(Double.parseDouble(input)));
    }

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(delimiter = '|', textBlock = """
            1e10              | 1e+10
            1e15              | 1e+15
            123e10            | 1.23e+12
            1e21              | 1e+21
            1e22              | 1e+22
            1e100             | 1e+100
            -1e100            | -1e+100
            1e-100            | 1e-100
            1e300             | 1e+300
            1.7976931348623157e308 | 1.79769e+308
            2.2250738585072014e-308 | 2.22507e-308
            4.9e-324          | 4.94066e-324
            """)
    void largeAndTinyExponents(String input, String expected) {
        assertEquals(expected, Strengths.format(Double.parseDouble(input)));
    }

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(delimiter = '|', textBlock = """
            999999.0          | 999999
            999999.4          | 999999
            999999.5          | 1e+06
            100000.5          | 100000
            100001.5          | 100002
            123456.5          | 123456
            123457.5          | 123458
            1234565.0         | 1.23456e+06
            1234575.0         | 1.23458e+06
            -56.65974         | -56.6597
            -56.65975         | -56.6598
            -56.659751        | -56.6598
            -67.12345         | -67.1235
            -67.123450001     | -67.1235
            12345.65          | 12345.6
            99999.95          | 99999.9
            1.000005          | 1.00001
            1.0000050000001   | 1.00001
            9.999995          | 10
            9.9999951         | 10
            -92.99999         | -93
            0.0001234565      | 0.000123457
            3.14159265358979  | 3.14159
            0.3333333333333333 | 0.333333
            -0.6666666666666666 | -0.666667
            """)
    void roundingToSixSignificantDigits(String input, String expected) {
        assertEquals(expected, Strengths.format(Double.parseDouble(input)));
    }

    @Test
    void nanAndInfinitiesUseTheTokensClientsParse() {
        assertEquals("NaN", Strengths.format(Double.NaN));
        assertEquals("NaN", Strengths.format(Double.longBitsToDouble(0xfff8000000000001L)));
        assertEquals("INF", Strengths.format(Double.POSITIVE_INFINITY));
        assertEquals("-INF", Strengths.format(Double.NEGATIVE_INFINITY));
    }

    @Test
    void zeroSigns() {
        assertEquals("0", Strengths.format(0.0));
        assertEquals("-0", Strengths.format(-0.0));
    }

    /**
     * A wider cross-check: random doubles over many magnitudes, typical dBm values, decimal
     * near-ties at the seventh digit and exact binary ties, given as exact hexadecimal doubles
     * (C's {@code %a}) with glibc's {@code %g} output.
     */
    @ParameterizedTest(name = "{0} -> {1}")
    @MethodSource("glibcTable")
    void matchesGlibcOnAGeneratedTable(String hex, String expected) {
        assertEquals(expected, Strengths.format(Double.parseDouble(hex)));
    }

    static Stream<org.junit.jupiter.params.provider.Arguments> glibcTable() {
        return GLIBC_TABLE.lines()
                .map(String::strip)
                .filter(line -> !line.isEmpty())
                .map(line -> line.split("\\|"))
                .map(parts -> org.junit.jupiter.params.provider.Arguments.of(parts[0].strip(), parts[1].strip()));
    }

    /** Generated with srand48(20080108); printf("%a|%g\n", v, v). */
    private static final String GLIBC_TABLE = """
            0x1.9eb04754a6249p-18 | 6.17934e-06
            -0x1.febd4515ff338p-51 | -8.85992e-16
            -0x1.0b140c697a48ep-49 | -1.85323e-15
            -0x1.0f22f345efa8ap-60 | -9.18646e-19
            -0x1.fabe30e74eecfp-48 | -7.03247e-15
            -0x1.3d2e84dad16fap-9 | -0.0024199
            0x1.225ab68d4afdfp-13 | 0.000138452
            -0x1.2936fde4e07adp+13 | -9510.87
            -0x1.7baa8fb548b5ap+19 | -777556
            0x1.8948db9466141p+34 | 2.63929e+10
            -0x1.79abf9f65c43cp+8 | -377.672
            0x1.bd7163e6506e7p+14 | 28508.3
            -0x1.8abe6a852a1d7p+42 | -6.78165e+12
            -0x1.eb3411f18f7d1p-40 | -1.74511e-12
            -0x1.3bf414ba14e68p+6 | -78.9884
            0x1.134b05ded1ab7p+45 | 3.7836e+13
            -0x1.b9a2c19d7413dp-23 | -2.05653e-07
            -0x1.1c665359611cap+13 | -9100.79
            0x1.aa80cc702154ap-64 | 9.03155e-20
            -0x1.796e1f071d3f6p+29 | -7.91528e+08
            0x1.4ff57306b7825p-8 | 0.00512632
            -0x1.266380c481a97p-17 | -8.77347e-06
            -0x1.dde4e3c49b9ecp+2 | -7.4671
            -0x1.3b87de6fcd47fp+65 | -4.54728e+19
            -0x1.fe79d2b72e8ffp-48 | -7.08428e-15
            0x1.05a3392d13c43p-4 | 0.0638764
            0x1.6a1139d710d56p-55 | 3.92554e-17
            0x1.ddecffa29685p+34 | 3.20731e+10
            0x1.0b23d09cfe4ecp-33 | 1.21481e-10
            -0x1.db7531bc5e748p-6 | -0.0290196
            -0x1.672fd6cb6e651p+16 | -91951.8
            0x1.92fd303bd9f17p+29 | 8.45129e+08
            0x1.d644976825db3p-18 | 7.00754e-06
            -0x1.7c723745284fcp+61 | -3.42675e+18
            -0x1.7c68925e80343p-53 | -1.64976e-16
            0x1.2849b652207efp-31 | 5.38945e-10
            0x1.1e1335e0d8894p-32 | 2.60184e-10
            -0x1.8a80fec1d390bp-34 | -8.96998e-11
            -0x1.7aaa1d6861565p+47 | -2.08173e+14
            0x1.cfedd8c483833p-47 | 1.28766e-14
            -0x1.8d82f9172eee4p-35 | -4.51918e-11
            -0x1.630830f8b53a9p-13 | -0.000169292
            -0x1.f3a7a7f712d9dp-52 | -4.33382e-16
            0x1.dc3aa54f7ab33p-6 | 0.0290667
            -0x1.11122645a3a4ap-30 | -9.93426e-10
            0x1.1e2b1e73bfc9bp-50 | 9.92846e-16
            0x1.d662b03a4fb2bp+47 | 2.58597e+14
            -0x1.c681504c5058bp-50 | -1.57688e-15
            -0x1.e957f878bb4cep-65 | -5.18113e-20
            -0x1.5e6e3b811a1cap+25 | -4.59316e+07
            -0x1.9944a79866384p-58 | -5.54662e-18
            0x1.dfa27210e60c9p+48 | 5.27364e+14
            -0x1.06feb619fa47dp+64 | -1.89508e+19
            0x1.b9315edc62737p+65 | 6.35826e+19
            0x1.1b11fb7375493p-14 | 6.74892e-05
            -0x1.1b38cc61415c9p-36 | -1.60993e-11
            -0x1.083bac39a8372p-42 | -2.34686e-13
            -0x1.07e81dbf9fb8dp+33 | -8.85524e+09
            -0x1.2ea2ef53d0369p+46 | -8.31881e+13
            -0x1.d84765123b231p+28 | -4.9522e+08
            -0x1.288b913625496p+6 | -74.1363
            -0x1.4925a724c928p+2 | -5.14292
            -0x1.78d55610e5d48p+4 | -23.5521
            -0x1.0d18bd4a63668p+5 | -33.6371
            -0x1.20b039bc34e6ep+6 | -72.1721
            -0x1.5b2c1f01ce88p+4 | -21.6983
            -0x1.09444a2cc80eap+6 | -66.3167
            -0x1.cbc60d09d20ecp+6 | -114.943
            -0x1.ed15200161b8cp+5 | -61.6353
            -0x1.495feb339853p+5 | -41.1718
            -0x1.7b37732b36c02p+6 | -94.8042
            -0x1.bf2691746ca24p+6 | -111.788
            -0x1.5b3a84fc1aa78p+4 | -21.7018
            -0x1.8a0c1cacf5a9p+6 | -98.5118
            -0x1.0d9d0133784dp+3 | -8.42542
            -0x1.f91a36fdb3b7p+4 | -31.5689
            -0x1.e9ef5c17f79ecp+5 | -61.2419
            -0x1.b64ab7c307a08p+6 | -109.573
            -0x1.ae85bb4e4d64p+1 | -3.36346
            -0x1.ac5bc95076714p+6 | -107.09
            -0x1.1c329e4cb7338p+4 | -17.7624
            -0x1.0abebf788c8p+3 | -8.33578
            -0x1.df5b2d4769928p+4 | -29.9598
            -0x1.afefd393e4accp+6 | -107.984
            -0x1.0538532c92226p+6 | -65.305
            -0x1.118ee1acd7bcp+3 | -8.54869
            -0x1.bf6bd26eb0ec4p+5 | -55.9276
            -0x1.403515825902p+3 | -10.0065
            -0x1.28944393ec9fcp+5 | -37.0724
            -0x1.97438c2c2357p+6 | -101.816
            -0x1.d2103p+19 | -954498
            0x1.6e9a176ddacefp+2 | 5.72816
            0x1.e2a0ded288ce7p+5 | 60.3285
            0x1.d4d9a95421c04p+2 | 7.32578
            -0x1.47073b07bde48p-8 | -0.00499006
            0x1.264c14p+22 | 4.82176e+06
            0x1.164f75cadcd1bp-21 | 5.18394e-07
            -0x1.36c5593b04b8dp-6 | -0.018968
            0x1.9b2714740ea31p-21 | 7.65831e-07
            -0x1.eda8cp+17 | -252754
            -0x1.cafac2a610ef3p-24 | -1.06864e-07
            0x1.1778d8p+21 | 2.28944e+06
            -0x1.85130a55e7bbbp-21 | -7.24708e-07
            -0x1.464628027d88cp-3 | -0.159313
            -0x1.576871ae6e12p-9 | -0.00261999
            -0x1.ca886594af4f1p+3 | -14.3292
            -0x1.49e09bea7acdbp-21 | -6.14444e-07
            0x1.6d5e7d38e5cfbp-9 | 0.00278755
            0x1.99a8826aa8eb4p+1 | 3.20045
            0x1.0150575b5b9b6p-7 | 0.0078526
            0x1.8358e56041893p+9 | 774.694
            0x1.a79f127f5e84fp-1 | 0.827385
            -0x1.b5f727136a401p+1 | -3.42161
            -0x1.6f45ccccccccdp+14 | -23505.5
            0x1.d84feb585bbf5p-23 | 2.19938e-07
            0x1.332038p+21 | 2.51598e+06
            0x1.33eb35b6cfc42p-17 | 9.17669e-06
            0x1.96ed24ad9fbb1p-18 | 6.06368e-06
            0x1.9063d30e2f6dbp-4 | 0.0977515
            0x1.f79c28f5c28f6p+5 | 62.9513
            -0x1.8b415p+19 | -809482
            0x1.cb66db2847ae5p-21 | 8.55702e-07
            0x1.a44302b40f66ap+1 | 3.28329
            0x1.35f0ed3d859c9p+1 | 2.42142
            0x1.1f5b9ab06ff4ep-7 | 0.00876947
            0x1.c3fdd65a14489p-5 | 0.0551748
            0x1.21f4d895beffcp-17 | 8.64137e-06
            -0x1.059e425aee632p+6 | -65.4046
            -0x1.3d3f333333333p+11 | -2537.97
            -0x1.c3a398201cd6p+0 | -1.76422
            0x1.e4367p+19 | 991668
            0x1.73f14p+17 | 190434
            0x1.b1dd8p+16 | 111070
            0x1.4d5e2p+18 | 341368
            0x1.165ecp+17 | 142526
            0x1.df717p+19 | 981900
            0x1.6f0ffp+19 | 751744
            0x1.aac29p+19 | 874004
            0x1.206a1p+19 | 590672
            0x1.a7004p+17 | 216576
            0x1.8113dp+19 | 788638
            0x1.e3737p+19 | 990108
            0x1.a317cp+17 | 214576
            0x1.249e1p+19 | 599280
            0x1.af4a5p+19 | 883282
            0x1.1691ep+18 | 285256
            0x1.4b284p+17 | 169552
            0x1.4b039p+19 | 677916
            0x1.e7f3dp+19 | 999326
            0x1.d7e5fp+19 | 966448
            0x1.b7d56cp+22 | 7.20624e+06
            0x1.341754p+22 | 5.04776e+06
            0x1.91129cp+22 | 6.57118e+06
            0x1.e9a5ecp+22 | 8.0224e+06
            0x1.c2fab4p+22 | 7.38884e+06
            0x1.0e8458p+21 | 2.21608e+06
            0x1.072b0ep+23 | 8.6235e+06
            0x1.946d48p+21 | 3.31306e+06
            0x1.155c4cp+22 | 4.54428e+06
            0x1.00ad4cp+22 | 4.2054e+06
            0x1.eb78f4p+22 | 8.05228e+06
            0x1.283ca4p+22 | 4.85354e+06
            0x1.1ae0f4p+22 | 4.63468e+06
            0x1.4cd37p+20 | 1.36326e+06
            0x1.0ffee6p+23 | 8.91276e+06
            0x1.570764p+22 | 5.62018e+06
            0x1.17aa42p+23 | 9.16406e+06
            0x1.802734p+22 | 6.29396e+06
            0x1.7f99b8p+21 | 3.14246e+06
            0x1.e90484p+22 | 8.01206e+06
            0x1.e847efae147aep+19 | 999999
            0x1.e847fp+19 | 1e+06
            0x1.e847f051eb852p+19 | 1e+06
            0x1.a36da54164f19p-14 | 9.99995e-05
            0x1.a36da540b0ccbp-14 | 9.99995e-05
            0x1.a36e20f366499p-14 | 0.0001
            0x1.a36e20f35445ep-14 | 0.0001
            0x1.869ff33333333p+16 | 99999.9
            0x1.869ff333226c4p+16 | 99999.9
            """;
}
