package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class MaterialRulesTest {

    private static final MaterialRules WCS = MaterialRules.parse(
            "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete");

    @Test
    void theFirstRuleMatchingAnyNameWinsWhateverTheCase() {
        assertEquals("brick", WCS.materialOf(List.of("Medium_wall_12", "link", "collision")));
        assertEquals("drywall", WCS.materialOf(List.of("building", "soft_wall_3", "c")));
        assertEquals("glass", WCS.materialOf(List.of("house", "link", "Window_Glass")));
        assertEquals("brick", WCS.materialOf(List.of("Medium_wall_glass")), "Medium_wall* comes before *glass*");
        assertEquals("concrete", WCS.materialOf(List.of("anything")));
        assertEquals("", MaterialRules.parse("door?=wood").materialOf(List.of("door12")), "? is one character");
        assertEquals("wood", MaterialRules.parse("door?=wood").materialOf(List.of("door1")));
        assertEquals("", MaterialRules.NONE.materialOf(List.of("Hard_wall")));
        assertEquals("", MaterialRules.parse(" ").materialOf(List.of("Hard_wall")));
        assertEquals("metal", MaterialRules.parse("a.b(c)=Metal").materialOf(List.of("A.B(C)")), "no regular expression");
        assertEquals(List.of("concrete", "brick", "drywall", "glass"), WCS.materials());
    }

    @Test
    void aRuleThatIsNotGlobEqualsMaterialIsRefused() {
        for (String bad : List.of("concrete", "=concrete", "wall=", "wall=con crete", "a=b,")) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MaterialRules.parse(bad), bad);
            assertEquals(true, e.getMessage().endsWith("is not GLOB=MATERIAL (a material is letters, digits, _ and -)"), e.getMessage());
        }
    }
}
