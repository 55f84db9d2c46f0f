// A STUB of the UnityEditor.ShortcutManagement members the package's Scene-view shortcuts use, written
// from Unity's Scripting Reference (2022.3; SR:<Page> as in UnityEditor.cs) and checked against the
// declarations in UnityCsReference 2022.3 (Modules/ShortcutManagerEditor/ShortcutAttribute.cs,
// ShortcutEntry.cs). NOT Unity's assembly: signatures only. Kept in its own file (issue 23, editor side).
#pragma warning disable CS1591
using System;
using UnityEngine;

namespace UnityEditor.ShortcutManagement
{
    public abstract class ShortcutBaseAttribute : Attribute { }                              // SR:ShortcutManagement.ShortcutBaseAttribute

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public class ShortcutAttribute : ShortcutBaseAttribute                                   // SR:ShortcutManagement.ShortcutAttribute
    {
        public string displayName { get; set; }                                             // SR:ShortcutManagement.ShortcutAttribute-displayName
        public ShortcutAttribute(string id, Type context = null) { }                         // SR:ShortcutManagement.ShortcutAttribute-ctor
        public ShortcutAttribute(string id, Type context, KeyCode defaultKeyCode, ShortcutModifiers defaultShortcutModifiers = ShortcutModifiers.None) { } // SR:ShortcutManagement.ShortcutAttribute-ctor
        public ShortcutAttribute(string id, Type context, string tag, KeyCode defaultKeyCode, ShortcutModifiers defaultShortcutModifiers = ShortcutModifiers.None) { } // SR:ShortcutManagement.ShortcutAttribute-ctor
        public ShortcutAttribute(string id, KeyCode defaultKeyCode, ShortcutModifiers defaultShortcutModifiers = ShortcutModifiers.None) { } // SR:ShortcutManagement.ShortcutAttribute-ctor
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public class ClutchShortcutAttribute : ShortcutAttribute                                 // SR:ShortcutManagement.ClutchShortcutAttribute
    {
        public ClutchShortcutAttribute(string id, Type context = null) : base(id, context) { } // SR:ShortcutManagement.ClutchShortcutAttribute-ctor
        public ClutchShortcutAttribute(string id, Type context, KeyCode defaultKeyCode, ShortcutModifiers defaultShortcutModifiers = ShortcutModifiers.None) : base(id, context, defaultKeyCode, defaultShortcutModifiers) { } // SR:ShortcutManagement.ClutchShortcutAttribute-ctor
        public ClutchShortcutAttribute(string id, KeyCode defaultKeyCode, ShortcutModifiers defaultShortcutModifiers = ShortcutModifiers.None) : base(id, defaultKeyCode, defaultShortcutModifiers) { } // SR:ShortcutManagement.ClutchShortcutAttribute-ctor
    }

    [Flags]
    public enum ShortcutModifiers { None = 0, Alt = 1, Action = 2, Shift = 4, Control = 8 } // SR:ShortcutManagement.ShortcutModifiers

    public enum ShortcutStage { Begin, End }                                                 // SR:ShortcutManagement.ShortcutStage

    public struct ShortcutArguments                                                          // SR:ShortcutManagement.ShortcutArguments
    {
        public object context;                                                               // SR:ShortcutManagement.ShortcutArguments-context
        public ShortcutStage stage;                                                          // SR:ShortcutManagement.ShortcutArguments-stage
    }
}
