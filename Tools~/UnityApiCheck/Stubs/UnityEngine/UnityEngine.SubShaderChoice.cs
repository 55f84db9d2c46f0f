// STUB members the renderer reads to notice a change of the SubShader Unity uses (the shader LOD, the
// render pipeline), in a file of their own so other stub edits merge cleanly. Same rules as
// UnityEngine.cs: written from the 2022.3 Scripting Reference (SR:<Page>) and checked against
// UnityCsReference 2022.3 (Runtime/Export/Shaders/Shader.bindings.cs: maximumLOD, the static
// globalMaximumLOD; Runtime/Export/Graphics/GraphicsSettings.bindings.cs: `public sealed partial class
// GraphicsSettings : Object`, the static currentRenderPipeline, get only;
// Runtime/Export/RenderPipeline/RenderPipelineAsset.cs: `public abstract class RenderPipelineAsset :
// ScriptableObject`).
#pragma warning disable CS1591

namespace UnityEngine
{
    public sealed partial class Shader                                               // SR:Shader
    {
        public int maximumLOD { get; set; }                                          // SR:Shader-maximumLOD
        public static int globalMaximumLOD { get; set; }                             // SR:Shader-globalMaximumLOD
    }
}

namespace UnityEngine.Rendering
{
    public abstract class RenderPipelineAsset : ScriptableObject { }                 // SR:Rendering.RenderPipelineAsset

    public sealed partial class GraphicsSettings : Object                            // SR:Rendering.GraphicsSettings
    {
        GraphicsSettings() { }
        public static RenderPipelineAsset currentRenderPipeline => null;             // SR:Rendering.GraphicsSettings-currentRenderPipeline
    }
}
