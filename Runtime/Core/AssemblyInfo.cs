using System.Runtime.CompilerServices;

// Core's machinery is internal; these assemblies build on it. The names are the asmdefs' (Unity) and
// the csprojs' (the off-Unity rig): the renderer, the editor's authoring code and tools, the Unity test
// assemblies, the dotnet test project and the rig's command-line tool.
[assembly: InternalsVisibleTo("GregoryTerrain.Runtime")]
[assembly: InternalsVisibleTo("GregoryTerrain.Authoring")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor")]
[assembly: InternalsVisibleTo("GregoryTerrain.Core.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Runtime.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Editor.Tests")]
[assembly: InternalsVisibleTo("GregoryTerrain.Tests")]
[assembly: InternalsVisibleTo("gt-cli")]
