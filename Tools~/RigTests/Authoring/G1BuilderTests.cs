using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class G1BuilderTests
    {
        static Double3 R(Random rng) => new Double3(2 * rng.NextDouble() - 1, 2 * rng.NextDouble() - 1, 2 * rng.NextDouble() - 1);

        static Double3 Cubic(Double3 p0, Double3 p1, Double3 p2, Double3 p3, double t) =>
            TestPatches.B3(0, t) * p0 + TestPatches.B3(1, t) * p1 + TestPatches.B3(2, t) * p2 + TestPatches.B3(3, t) * p3;

        [Test]
        public void CrossBoundarySatisfiesTheG1Equation()
        {
            // B(t) = k(t) A(t) + h(t) C(t), with A the cubic of A0, (2A0+A3)/3, (A0+2A3)/3, A3,
            // C the quadratic Bezier of C0..C2, k and h linear: checked at many t.
            var rng = new Random(4);
            for (int n = 0; n < 50; n++)
            {
                Double3 a0 = R(rng), a3 = R(rng), c0 = R(rng), c1 = R(rng), c2 = R(rng);
                double k0 = -0.5 - rng.NextDouble(), k1 = -0.5 - rng.NextDouble(), h0 = rng.NextDouble() - 0.5, h1 = rng.NextDouble() - 0.5;
                G1Builder.CrossBoundary(a0, a3, c0, c1, c2, k0, k1, h0, h1, out Double3 b0, out Double3 b1, out Double3 b2, out Double3 b3);
                Double3 a1 = (2 * a0 + a3) / 3, a2 = (a0 + 2 * a3) / 3;
                for (int s = 0; s <= 20; s++)
                {
                    double t = s / 20.0;
                    Double3 A = Cubic(a0, a1, a2, a3, t);
                    Double3 C = (1 - t) * (1 - t) * c0 + 2 * t * (1 - t) * c1 + t * t * c2;
                    Double3 rhs = ((1 - t) * k0 + t * k1) * A + ((1 - t) * h0 + t * h1) * C;
                    Assert.That(TestPatches.Dist(Cubic(b0, b1, b2, b3, t), rhs), Is.LessThan(1e-14));
                }
            }
        }

        [Test]
        public void CornerScalarsRecoverACombination()
        {
            var rng = new Random(8);
            Double3 a = R(rng), c = R(rng);
            G1Builder.SolveCornerScalars(a, -0.7 * a + 0.3 * c, c, out double k, out double h, out double res);
            Assert.That(k, Is.EqualTo(-0.7).Within(1e-14));
            Assert.That(h, Is.EqualTo(0.3).Within(1e-14));
            Assert.That(res, Is.LessThan(1e-14));
            var ex = Assert.Throws<ArgumentException>(() => G1Builder.SolveCornerScalars(a, c, 2 * a, out _, out _, out _));
            Assert.That(ex.Message, Does.Contain("parallel"));
        }

        /// <summary>
        /// A grid on a smooth surface F(x, y) with a non-linear x, y parametrisation (so h != 0 and k
        /// varies): boundary curves by Hermite from F's partial derivatives, so corner tangent planes
        /// are consistent; interior points random. MakeG1 must make it G1.
        /// </summary>
        static PatchGrid CurvedGrid(int n, int m, int seed)
        {
            Double3 F(double x, double y) => new Double3(x + 0.08 * Math.Sin(3 * y), y + 0.06 * Math.Sin(2 * x + y), 0.2 * Math.Sin(4 * x) * Math.Cos(3 * y));
            Double3 Fx(double x, double y) => new Double3(1, 0.12 * Math.Cos(2 * x + y), 0.8 * Math.Cos(4 * x) * Math.Cos(3 * y));
            Double3 Fy(double x, double y) => new Double3(0.24 * Math.Cos(3 * y), 1 + 0.06 * Math.Cos(2 * x + y), -0.6 * Math.Sin(4 * x) * Math.Sin(3 * y));
            var grid = PatchGrid.CreateFlat(n, m, new[] { 0, 0.3, 0.55, 1.0 }.AsSpan(0, n + 1).ToArray(), PatchGrid.UniformLines(m));
            var rng = new Random(seed);
            for (int j = 0; j < m; j++)
                for (int i = 0; i < n; i++)
                {
                    var p = grid.Patch(i, j);
                    double x0 = grid.XLines[i], x1 = grid.XLines[i + 1], y0 = grid.YLines[j], y1 = grid.YLines[j + 1];
                    double wx = x1 - x0, wy = y1 - y0;
                    for (int a = 0; a < 4; a += 3)
                        for (int b = 0; b < 4; b += 3)
                        {
                            double x = a == 0 ? x0 : x1, y = b == 0 ? y0 : y1;
                            int sa = a == 0 ? 1 : -1, sb = b == 0 ? 1 : -1;
                            p[GregoryPatch.Slot(a, b)] = F(x, y);
                            p[GregoryPatch.Slot(a + sa, b)] = F(x, y) + (sa * wx / 3) * Fx(x, y);
                            p[GregoryPatch.Slot(a, b + sb)] = F(x, y) + (sb * wy / 3) * Fy(x, y);
                        }
                    foreach (int s in new[] { 5, 6, 9, 10, 16, 17, 18, 19 })
                        p[s] = p[s] + new Double3(0, 0, 0.05 * (2 * rng.NextDouble() - 1));
                }
            return grid;
        }

        [Test]
        public void MakeG1JoinsACurvedGrid()
        {
            var grid = CurvedGrid(3, 3, 1);
            grid.Validate();
            double before = ContinuityMeasure.MaxNormalAngleDegrees(grid);
            G1Builder.MakeG1(grid);
            double after = ContinuityMeasure.MaxNormalAngleDegrees(grid);
            TestContext.Out.WriteLine($"curved 3x3 grid: max normal angle across shared edges {before:F3} deg before, {after:E3} deg after MakeG1");
            Assert.That(before, Is.GreaterThan(1.0));
            Assert.That(after, Is.LessThan(1e-8));
            Assert.That(ContinuityMeasure.MaxPositionGap(grid), Is.EqualTo(0.0));
            Assert.DoesNotThrow(grid.Validate);
        }

        [Test]
        public void MakeG1RejectsInconsistentCornerAndLeavesGridUnchanged()
        {
            var grid = CurvedGrid(3, 2, 2);
            // Tilt one corner's tangent out of the plane on one side only.
            var p = grid.Patch(1, 1);
            int s = GregoryPatch.Slot(1, 0);
            var snapshot = grid.Clone();
            p[s] = p[s] + new Double3(0, 0, 0.05);
            grid.Patch(1, 0)[GregoryPatch.Slot(1, 3)] = p[s]; // keep the shared edge identical
            var changed = grid.Clone();
            var ex = Assert.Throws<ArgumentException>(() => G1Builder.MakeG1(grid));
            Assert.That(ex.Message, Does.Contain("patch (").And.Contain("not consistent"));
            for (int k = 0; k < grid.PatchCount; k++)
                for (int q = 0; q < 20; q++)
                    Assert.That(grid.Patches[k][q], Is.EqualTo(changed.Patches[k][q]));
            Assert.That(snapshot.Patches[0][0], Is.EqualTo(grid.Patches[0][0]));
        }
    }
}
