// STUB of the Unity Test Framework's (com.unity.test-framework, assembly UnityEngine.TestRunner)
// UnityPlatformAttribute and LogAssert, for the Unity-side test checks. Declared as the Test
// Framework declares them (LogAssert: UnityEngine.TestRunner/TestRunner/Messages/LogAssert.cs, a static
// class). UnityPlatformAttribute (UnityEngine.TestRunner/NUnitExtensions/Attributes/
// UnityPlatformAttribute.cs): a class (not sealed) deriving NUnitAttribute and IApplyToTest, usable on
// assemblies, classes and methods, AllowMultiple = true, Inherited = false; include and exclude are
// get/set properties. The body here applies nothing: only the signatures matter. SR: here names the
// page of the Test Framework package's API reference (UnityEngine.TestTools.UnityPlatformAttribute).
#pragma warning disable CS1591
using System;
using System.Text.RegularExpressions;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;

namespace UnityEngine.TestTools
{
    [AttributeUsage(AttributeTargets.Assembly | AttributeTargets.Class | AttributeTargets.Method, AllowMultiple = true, Inherited = false)]
    public class UnityPlatformAttribute : NUnitAttribute, IApplyToTest              // SR:TestTools.UnityPlatformAttribute
    {
        public RuntimePlatform[] include { get; set; }                              // SR:TestTools.UnityPlatformAttribute-include
        public RuntimePlatform[] exclude { get; set; }                              // SR:TestTools.UnityPlatformAttribute-exclude
        public UnityPlatformAttribute() { include = new RuntimePlatform[0]; exclude = new RuntimePlatform[0]; } // SR:TestTools.UnityPlatformAttribute-ctor
        public UnityPlatformAttribute(params RuntimePlatform[] include) : this() { this.include = include; } // SR:TestTools.UnityPlatformAttribute-ctor
        public void ApplyToTest(Test test) { }                                      // SR:TestTools.UnityPlatformAttribute.ApplyToTest
    }

    public static class LogAssert                                                     // SR:TestTools.LogAssert
    {
        public static void Expect(LogType type, string message) { }                   // SR:TestTools.LogAssert.Expect
        public static void Expect(LogType type, Regex message) { }                    // SR:TestTools.LogAssert.Expect
    }
}
