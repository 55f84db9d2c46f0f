using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The rational blend is 0/0 at each corner; approaching every corner along several directions,
    /// down to subnormal distances, values must stay finite and converge to the corner's.
    /// </summary>
    [TestFixture]
    public class GregoryCornerTests
    {
        static readonly (double u, double v, int slot)[] Corners =
            { (0, 0, GregoryPatch.Corner00), (0, 1, GregoryPatch.Corner03), (1, 0, GregoryPatch.Corner30), (1, 1, GregoryPatch.Corner33) };
        static readonly double[] AnglesDeg = { 0, 1e-3, 10, 30, 45, 60, 89.999, 90 };

        [TestCase(1e-7)]
        [TestCase(1e-20)]
        [TestCase(4.9e-324)]
        public void DoubleApproachesCorners(double d)
        {
            var g = TestPatches.Random(31);
            foreach (var c in Corners)
            {
                GregoryEval.Evaluate(g.Points, c.u, c.v, out Double3 p0, out Double3 du0, out Double3 dv0);
                foreach (double deg in AnglesDeg)
                {
                    double a = deg * Math.PI / 180;
                    // Step inwards: +d from 0, -d from 1 (1 - d may round to 1: then we are at the corner).
                    double u = c.u == 0 ? d * Math.Cos(a) : 1 - d * Math.Cos(a);
                    double v = c.v == 0 ? d * Math.Sin(a) : 1 - d * Math.Sin(a);
                    GregoryEval.Evaluate(g.Points, u, v, out Double3 p, out Double3 du, out Double3 dv);
                    string where = $"corner ({c.u}, {c.v}), d = {d:E2}, angle {deg}";
                    Assert.That(p.IsFinite && du.IsFinite && dv.IsFinite, Is.True, where);
                    double dist = Math.Max(Math.Abs(u - c.u), Math.Abs(v - c.v));
                    // Lipschitz bounds: derivatives of the patch are O(10) here, second derivatives O(1e3).
                    Assert.That(TestPatches.Dist(p, p0), Is.LessThanOrEqualTo(100 * dist + 1e-15), where);
                    Assert.That(TestPatches.Dist(du, du0), Is.LessThanOrEqualTo(1e4 * dist + 1e-13), where);
                    Assert.That(TestPatches.Dist(dv, dv0), Is.LessThanOrEqualTo(1e4 * dist + 1e-13), where);
                }
            }
        }

        [TestCase(1e-7f)]
        [TestCase(1e-20f)]
        [TestCase(1.4e-45f)]
        public void FloatApproachesCorners(float d)
        {
            var g = TestPatches.Random(32);
            Float3[] f = TestPatches.ToFloat(g);
            foreach (var c in Corners)
            {
                GregoryEval.Evaluate(f, (float)c.u, (float)c.v, out Float3 p0, out Float3 du0, out Float3 dv0);
                foreach (double deg in AnglesDeg)
                {
                    double a = deg * Math.PI / 180;
                    float du_ = (float)(d * Math.Cos(a)), dv_ = (float)(d * Math.Sin(a));
                    float u = c.u == 0 ? du_ : 1f - du_;
                    float v = c.v == 0 ? dv_ : 1f - dv_;
                    GregoryEval.Evaluate(f, u, v, out Float3 p, out Float3 du, out Float3 dv);
                    string where = $"corner ({c.u}, {c.v}), d = {d:E2}, angle {deg}, (u, v) = ({u:R}, {v:R})";
                    Assert.That(p.IsFinite && du.IsFinite && dv.IsFinite, Is.True, where);
                    double dist = Math.Max(Math.Abs((double)u - c.u), Math.Abs((double)v - c.v));
                    // Float rounding adds a few ulps of the O(1..10) values.
                    Assert.That(TestPatches.Dist(p, p0), Is.LessThanOrEqualTo(100 * dist + 1e-6), where);
                    Assert.That(TestPatches.Dist(du, du0), Is.LessThanOrEqualTo(1e4 * dist + 1e-5), where);
                    Assert.That(TestPatches.Dist(dv, dv0), Is.LessThanOrEqualTo(1e4 * dist + 1e-5), where);
                }
            }
        }

        [Test]
        public void DerivativeConvergesAlongDirectionsAtTheCorner()
        {
            // The corner derivative equals the limit from inside: compare the guarded value at the
            // corner with the derivative at 1e-9 along several directions (no guard involved there).
            var g = TestPatches.Random(33);
            foreach (var c in Corners)
            {
                GregoryEval.Evaluate(g.Points, c.u, c.v, out _, out Double3 du0, out Double3 dv0);
                foreach (double deg in new[] { 5.0, 45.0, 85.0 })
                {
                    double a = deg * Math.PI / 180, d = 1e-9;
                    double u = c.u == 0 ? d * Math.Cos(a) : 1 - d * Math.Cos(a);
                    double v = c.v == 0 ? d * Math.Sin(a) : 1 - d * Math.Sin(a);
                    GregoryEval.Evaluate(g.Points, u, v, out _, out Double3 du, out Double3 dv);
                    Assert.That(TestPatches.Dist(du, du0), Is.LessThan(1e-5));
                    Assert.That(TestPatches.Dist(dv, dv0), Is.LessThan(1e-5));
                }
            }
        }
    }
}
