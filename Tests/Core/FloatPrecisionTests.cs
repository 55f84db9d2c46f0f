using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class FloatPrecisionTests
    {
        [Test]
        public void FloatEvaluatorDeviationOnAFitted5x5Grid()
        {
            PatchGrid g = HeightmapFitterTests.Fit5x5().Grid;
            var floats = new Float3[g.PatchCount][];
            for (int p = 0; p < g.PatchCount; p++) floats[p] = TestPatches.ToFloat(g.Patches[p]);
            var rng = new Random(12345);
            double worstPos = 0, worstZ = 0, worstAngle = 0;
            for (int n = 0; n < 100000; n++)
            {
                int p = rng.Next(g.PatchCount);
                double u = rng.NextDouble(), v = rng.NextDouble();
                // The same (u, v) for both: the float one is rounded first and the reference uses it.
                float uf = (float)u, vf = (float)v;
                GregoryEval.Evaluate(floats[p], uf, vf, out Float3 pf, out _, out _);
                Double3 pd = GregoryEval.Position(g.Patches[p].Points, uf, vf);
                worstPos = Math.Max(worstPos, GMath.length((Double3)pf - pd));
                worstZ = Math.Max(worstZ, Math.Abs(pf.z - pd.z));
                Double3 nf = GregoryEval.Normal(floats[p], uf, vf), nd = GregoryEval.Normal(g.Patches[p].Points, uf, vf);
                worstAngle = Math.Max(worstAngle, Math.Atan2(GMath.length(GMath.cross(nf, nd)), GMath.dot(nf, nd)) * 180 / Math.PI);
            }
            TestContext.Out.WriteLine($"float vs double evaluator, 100,000 random (u, v) on a fitted 5x5 grid: max position deviation {worstPos:E3} (z only {worstZ:E3}), max normal deviation {worstAngle:E3} deg");
            // Control points and results are O(1): a few float ulps (6e-8 each) of error is expected.
            Assert.That(worstPos, Is.LessThan(1e-6));
            Assert.That(worstAngle, Is.LessThan(1e-3));
        }
    }
}
