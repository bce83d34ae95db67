package gfx.tick1.engine.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class Vector3Test {

    private static final Vector3 A = new Vector3(1, -2, 3);
    private static final Vector3 B = new Vector3(-4, 5, 0.5);

    @Test
    void uniformConstructorFillsAllThreeComponents() {
        assertThat(new Vector3(0.25)).isEqualTo(new Vector3(0.25, 0.25, 0.25));
    }

    @Test
    void addAndSubtractWorkComponentWise() {
        assertThat(A.add(B)).isEqualTo(new Vector3(-3, 3, 3.5));
        assertThat(A.subtract(B)).isEqualTo(new Vector3(5, -7, 2.5));
    }

    @Test
    void scaleByNumberAndByVector() {
        assertThat(A.scale(2)).isEqualTo(new Vector3(2, -4, 6));
        assertThat(A.scale(B)).isEqualTo(new Vector3(-4, -10, 1.5));
    }

    @Test
    void dotProductIsTheSumOfComponentProducts() {
        assertThat(A.dot(B)).isEqualTo(-4 - 10 + 1.5);
    }

    @Test
    void crossProductIsPerpendicularToBothFactors() {
        Vector3 c = A.cross(B);
        assertThat(c.dot(A)).isCloseTo(0, within(1e-12));
        assertThat(c.dot(B)).isCloseTo(0, within(1e-12));
        assertThat(new Vector3(1, 0, 0).cross(new Vector3(0, 1, 0))).isEqualTo(new Vector3(0, 0, 1));
    }

    @Test
    void magnitudeIsEuclideanLength() {
        assertThat(new Vector3(3, 4, 12).magnitude()).isEqualTo(13);
    }

    @Test
    void normalisedVectorHasUnitLengthAndSameDirection() {
        Vector3 n = A.normalised();
        assertThat(n.magnitude()).isCloseTo(1, within(1e-15));
        assertThat(n.cross(A).magnitude()).isCloseTo(0, within(1e-15));
        assertThat(n.dot(A)).isPositive();
    }

    @Test
    void reflectionInANormalKeepsLengthAndMirrorsTheAngle() {
        Vector3 N = new Vector3(0.2, 1, -0.3).normalised();
        Vector3 L = new Vector3(1, 2, 0.5).normalised();
        Vector3 R = L.reflectIn(N);
        assertThat(R.magnitude()).as("|R|").isCloseTo(1, within(1e-15));
        assertThat(R.dot(N)).as("R.N equals L.N").isCloseTo(L.dot(N), within(1e-15));
        assertThat(R.add(L).cross(N).magnitude()).as("R + L is parallel to N").isCloseTo(0, within(1e-15));
    }

    @Test
    void reflectionIsMirrorLikeNotABounce() {
        // Handout footnote 1: a vector along the normal reflects to itself.
        Vector3 N = new Vector3(0, 1, 0);
        assertThat(new Vector3(0, 1, 0).reflectIn(N)).isEqualTo(new Vector3(0, 1, 0));
        assertThat(new Vector3(1, 1, 0).reflectIn(N)).isEqualTo(new Vector3(-1, 1, 0));
    }

    @Test
    void toRgbTruncatesTowardsZeroInsteadOfRounding() {
        assertThat(new Vector3(0.1).toRGB()).as("background 0.1 * 255 = 25.5").isEqualTo(0x191919);
        assertThat(Vector3.toByte(254.9 / 255)).isEqualTo(254);
    }

    @Test
    void toRgbClampsEachChannelToTheByteRange() {
        assertThat(new Vector3(-0.5, 1.7, 1).toRGB()).isEqualTo(0x00FFFF);
    }

    @Test
    void toRgbPacksRedGreenBlueInThatOrder() {
        assertThat(new Vector3(1, 0, 0).toRGB()).isEqualTo(0xFF0000);
        assertThat(new Vector3(0, 1, 0).toRGB()).isEqualTo(0x00FF00);
        assertThat(new Vector3(0, 0, 1).toRGB()).isEqualTo(0x0000FF);
    }

    @Test
    void notANumberChannelBecomesBlackRatherThanGarbage() {
        assertThat(Vector3.toByte(Double.NaN)).isZero();
    }

    @Test
    void equalityComparesAllThreeComponents() {
        assertThat(A.equals(new Vector3(1, -2, 3))).isTrue();
        assertThat(A.equals(new Vector3(1, -2, 3.0000001))).isFalse();
        assertThat(A).hasSameHashCodeAs(new Vector3(1, -2, 3));
    }
}
