using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The package's public API stays small and deliberate: the types the Core, Runtime, Authoring and Editor
    /// assemblies export (as Tools~/UnityApiCheck builds them, editor and player flavours) are read
    /// from the assemblies' metadata and must all be on <see cref="Allowed"/>, at most
    /// <see cref="MaxPublicTypes"/> of them. A type made public by accident fails here; one made public
    /// on purpose goes on the list (and into Documentation~/api.md) with the change.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PublicApiTests
    {
        const int MaxPublicTypes = 20;

        static readonly string[] Allowed =
        {
            // Runtime: the components, the asset and the helpers users call.
            "GregoryTerrain.GregoryTerrainRenderer",
            "GregoryTerrain.GregoryTerrainSurface",   // the renderer's queries (renderer.Surface)
            "GregoryTerrain.PatchGridAsset",
            "GregoryTerrain.CameraRangeController",
            "GregoryTerrain.ZoomRangeController",
            "GregoryTerrain.RangeFit",
            "GregoryTerrain.SnowSimulator",
            "GregoryTerrain.GregoryTerrainCollider",
            "GregoryTerrain.VertexEvaluation",
            // Core: the values those take and return.
            "GregoryTerrain.TerrainRange",
            "GregoryTerrain.TriangleEstimate",
            "GregoryTerrain.NoiseSettings",
            "GregoryTerrain.HeightColorSettings",
            "GregoryTerrain.TessellationSettings",
            "GregoryTerrain.SnowSettings",
            "GregoryTerrain.SnowField",
            "GregoryTerrain.Float2",
            "GregoryTerrain.Float3",
        };

        static readonly string[] Assemblies =
        {
            Path.Combine("EditorCheck", "bin", "Release", "netstandard2.1", "GregoryTerrain.Core.dll"),
            Path.Combine("EditorCheck", "bin", "Release", "netstandard2.1", "GregoryTerrain.Runtime.dll"),
            Path.Combine("EditorCheck", "bin", "Release", "netstandard2.1", "GregoryTerrain.Editor.dll"),
            Path.Combine("EditorCheck", "bin", "Release", "netstandard2.1", "GregoryTerrain.Authoring.dll"),
            Path.Combine("RuntimePlayer", "bin", "Release", "netstandard2.1", "GregoryTerrain.Runtime.dll"),
        };

        [Test]
        public void OnlyTheListedTypesArePublic()
        {
            UnityApiCheckTests.Build();
            var exported = new SortedSet<string>();
            foreach (string rel in Assemblies)
            {
                string path = PackageRoot.Combine("Tools~", "UnityApiCheck", rel);
                Assert.That(File.Exists(path), Is.True, $"{path} was not built");
                exported.UnionWith(ExportedTypes(path));
            }
            TestContext.Out.WriteLine($"{exported.Count} public types:\n  " + string.Join("\n  ", exported));

            Assert.That(exported.Except(Allowed), Is.Empty, "public types not on the allow-list (make them internal, or list and document them)");
            Assert.That(Allowed.Except(exported), Is.Empty, "allow-list entries no assembly exports (remove them)");
            Assert.That(exported.Count, Is.LessThanOrEqualTo(MaxPublicTypes), "public types");
        }

        /// <summary>Full names of the types visible outside the assembly: public top-level types and the public nested types of those.</summary>
        static IEnumerable<string> ExportedTypes(string path)
        {
            using var stream = File.OpenRead(path);
            using var pe = new PEReader(stream);
            MetadataReader md = pe.GetMetadataReader();
            foreach (TypeDefinitionHandle h in md.TypeDefinitions)
            {
                if (!IsVisible(md, h)) continue;
                TypeDefinition t = md.GetTypeDefinition(h);
                string name = md.GetString(t.Name);
                for (TypeDefinitionHandle outer = t.GetDeclaringType(); !outer.IsNil; outer = md.GetTypeDefinition(outer).GetDeclaringType())
                {
                    name = md.GetString(md.GetTypeDefinition(outer).Name) + "+" + name;
                    t = md.GetTypeDefinition(outer);
                }
                string ns = md.GetString(t.Namespace);
                yield return ns.Length > 0 ? ns + "." + name : name;
            }
        }

        static bool IsVisible(MetadataReader md, TypeDefinitionHandle h)
        {
            TypeDefinition t = md.GetTypeDefinition(h);
            TypeAttributes v = t.Attributes & TypeAttributes.VisibilityMask;
            TypeDefinitionHandle outer = t.GetDeclaringType();
            if (outer.IsNil) return v == TypeAttributes.Public;
            bool nestedVisible = v == TypeAttributes.NestedPublic || v == TypeAttributes.NestedFamily || v == TypeAttributes.NestedFamORAssem;
            return nestedVisible && IsVisible(md, outer);
        }
    }
}
