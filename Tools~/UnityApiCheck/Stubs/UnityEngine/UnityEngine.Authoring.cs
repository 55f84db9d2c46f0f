// STUB members of UnityEngine's IMGUI used by the sculpt tool (issue 27, deliverable 3), checked
// against UnityCsReference 2022.3: Modules/IMGUI/Event.bindings.cs, Event.cs, GUIUtility.cs,
// GUIEnums.cs. SR:<Page> as in UnityEngine.cs. NOT Unity's assembly: signatures only.
#pragma warning disable CS1591

namespace UnityEngine
{
    public enum FocusType { Keyboard = 1, Passive = 2 }                                     // SR:FocusType (Native = 0 is obsolete)

    public partial class GUIUtility                                                          // SR:GUIUtility (partial in 2022.3)
    {
        public static int GetControlID(FocusType focus) => 0;                                // SR:GUIUtility.GetControlID
    }

    public sealed partial class Event
    {
        public Vector2 mousePosition { get; set; }                                           // SR:Event-mousePosition
        public int button { get; set; }                                                      // SR:Event-button
        public bool shift { get => false; set { } }                                          // SR:Event-shift
        public bool alt { get => false; set { } }                                            // SR:Event-alt
        public void Use() { }                                                                // SR:Event.Use
    }
}
