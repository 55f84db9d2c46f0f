// The figures of the issue "Hard cases stay numerically stable", counted from the test fixtures
// themselves (each [Test] is one case, each [TestCase] one more): named hard cases on the CPU
// (Tests/Core/HardCaseTests) and the GPU (HardCaseGpuTests), bad-input cases (BadInputTests), and
// the property iterations of PropertyTests (CPU) and GpuPropertyTests (GPU). Whether they pass is
// the run's own summary; the jitter tables are printed by DeepZoomTests and DeepZoomGpuTests.
using System;
using System.Linq;
using System.Reflection;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class IssueFiguresTests
    {
        static int CaseCount(Type fixture) =>
            fixture.GetMethods(BindingFlags.Public | BindingFlags.Instance)
                   .Sum(m => m.GetCustomAttributes<TestCaseAttribute>().Count() + (m.GetCustomAttribute<TestAttribute>() != null ? 1 : 0));

        // Cases of a fixture whose test name says it feeds bad input ("Bad").
        static int BadInputCaseCount(Type fixture) =>
            fixture.GetMethods(BindingFlags.Public | BindingFlags.Instance).Where(m => m.Name.Contains("Bad"))
                   .Sum(m => m.GetCustomAttributes<TestCaseAttribute>().Count() + (m.GetCustomAttribute<TestAttribute>() != null ? 1 : 0));

        [Test]
        public void CountsOfTheHardCaseIssue()
        {
            int cpu = CaseCount(typeof(HardCaseTests)), gpu = CaseCount(typeof(HardCaseGpuTests));
            // The jitter measure's bad width moved with ZoomJitter to the rig (ZoomJitterTests).
            int bad = CaseCount(typeof(BadInputTests)) + BadInputCaseCount(typeof(ZoomJitterTests));
            TestContext.Out.WriteLine($"named hard cases: {cpu} CPU (HardCaseTests) + {gpu} GPU (HardCaseGpuTests) = {cpu + gpu}");
            TestContext.Out.WriteLine($"bad-input cases (BadInputTests, ZoomJitterTests' bad width): {bad}");
            TestContext.Out.WriteLine($"property iterations: {PropertyTests.Grids * PropertyTests.RangesPerGrid} CPU (PropertyTests: {PropertyTests.Grids} grids x {PropertyTests.RangesPerGrid} ranges), " +
                                      $"{GpuPropertyTests.Grids * GpuPropertyTests.RangesPerGrid} GPU (GpuPropertyTests: {GpuPropertyTests.Grids} fitted grids x {GpuPropertyTests.RangesPerGrid} random ranges, one readback draw each)");
            TestContext.Out.WriteLine("deep-zoom jitter tables: DeepZoomTests (CPU, noise off and on), DeepZoomGpuTests (GPU, noise off and on)");
            Assert.That(cpu, Is.GreaterThanOrEqualTo(20));
            Assert.That(gpu, Is.GreaterThanOrEqualTo(17));
            Assert.That(bad, Is.GreaterThanOrEqualTo(39));
        }
    }
}
