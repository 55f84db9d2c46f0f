// STUB members of UnityEngine's IMGUI used by the editor tools' fixes for issue 36 (the sculpt
// tool's hot control, leaving the GUI after a modal dialog, the heightmap's compression check), checked
// against UnityCsReference 2022.3: Modules/IMGUI/GUIUtility.cs, Modules/IMGUI/Event.bindings.cs,
// Runtime/Export/Graphics/GraphicsFormatUtility.bindings.cs. SR:<Page> as in UnityEngine.cs.
// NOT Unity's assembly: signatures only.
#pragma warning disable CS1591

namespace UnityEngine
{
    public partial class GUIUtility
    {
        public static int hotControl { get => 0; set { } }                                   // SR:GUIUtility-hotControl
        public static int GetControlID(int hint, FocusType focus) => 0;                       // SR:GUIUtility.GetControlID
        public static void ExitGUI() { }                                                     // SR:GUIUtility.ExitGUI (throws ExitGUIException in Unity)
    }

    public sealed partial class Event
    {
        public EventType GetTypeForControl(int controlID) => default;                       // SR:Event.GetTypeForControl
    }
}

namespace UnityEngine.Experimental.Rendering
{
    public class GraphicsFormatUtility                                                       // SR:Experimental.Rendering.GraphicsFormatUtility
    {
        public static bool IsCompressedFormat(TextureFormat format) => false;               // SR:Experimental.Rendering.GraphicsFormatUtility.IsCompressedFormat
    }
}
