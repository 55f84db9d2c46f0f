using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Static checks over the renderer's C# (Runtime/GregoryTerrainRenderer*.cs and its owners) for state that only a
    /// Unity editor could show going wrong: what the property block is known to hold once it is
    /// cleared, the draw's bounds against the shader's tile culling, what the draw mode is cached
    /// against, the device check before any structured buffer, and the range origin per camera.
    /// The Unity-side tests (Tests/Runtime) check the same in Unity; each check here is also run on
    /// the broken code it replaces, which it must reject.
    /// </summary>
    [TestFixture]
    public class RendererStateSourceTests
    {
        static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        /// <summary>The component's files, then the owners it holds (its per-camera frame, its cache's frame, its GPU buffers, its material copy).</summary>
        static string RendererCode() => string.Join("\n",
            Directory.GetFiles(PackageRoot.Combine("Runtime"), "GregoryTerrainRenderer*.cs").OrderBy(f => f)
                .Concat(new[] { "TerrainFrameDriver.cs", "VertexCachePass.cs", "TerrainGpuBuffers.cs", "DrawMaterialCopy.cs" }.Select(f => PackageRoot.Combine("Runtime", f)))
                .Select(f => StripComments(File.ReadAllText(f))));

        /// <summary>The body (braces included) of the method or property declared as <paramref name="name"/>, or null.</summary>
        internal static string Body(string code, string name)
        {
            Match m = Regex.Match(code, $@"\b{Regex.Escape(name)}\s*(\([^)]*\))?\s*(?=\{{)");
            if (!m.Success) return null;
            int start = m.Index + m.Length, depth = 0;
            for (int i = start; i < code.Length; i++)
            {
                if (code[i] == '{') depth++;
                else if (code[i] == '}' && --depth == 0) return code.Substring(start, i - start + 1);
            }
            return null;
        }

        /// <summary>The name of the method whose body holds <paramref name="index"/>.</summary>
        static string EnclosingMethod(string code, int index)
        {
            foreach (Match m in Regex.Matches(code.Substring(0, index), @"\b(\w+)\s*\([^)]*\)\s*\{").Cast<Match>().Reverse())
            {
                string body = Body(code.Substring(m.Index), m.Groups[1].Value);
                if (body != null && m.Index + m.Length - 1 + body.Length > index) return m.Groups[1].Value;
            }
            return null;
        }

        // ---- 1. What the property block holds, forgotten with it ----------------------------------

        /// <summary>
        /// Memos of what the property block holds (fields named <c>_sent*</c> / <c>_bound*</c>) that
        /// the one method clearing the block does not reset: after the clear each would skip sending
        /// a value the block no longer has. Also a problem: the block cleared in more than one place.
        /// </summary>
        internal static List<string> MemosNotResetWithTheBlock(string code)
        {
            var problems = new List<string>();
            var clears = Regex.Matches(code, @"_props\s*\??\s*\.\s*Clear\s*\(\s*\)");
            if (clears.Count != 1) { problems.Add($"the property block is cleared in {clears.Count} places, not one"); if (clears.Count == 0) return problems; }
            string method = EnclosingMethod(code, clears[0].Index);
            string body = Body(code, method) ?? "";
            var memos = Regex.Matches(code, @"(?<![\w.])(_(?:sent|bound)\w*)").Select(m => m.Groups[1].Value).Distinct();
            foreach (string memo in memos)
                if (!Regex.IsMatch(body, $@"\b{memo}\s*=(?!=)"))
                    problems.Add($"{memo} is not reset in {method}, which clears the property block");
            // Bindings Core's FrameState remembers (BindNoiseCells, BindSnow) are reset by its Forget.
            if (Regex.IsMatch(code, @"_state\.Bind\w+\s*\(") && !Regex.IsMatch(body, @"_state\.Forget\s*\(\s*\)"))
                problems.Add($"{method} clears the property block without _state.Forget(), which resets the bindings FrameState remembers");
            return problems;
        }

        [Test]
        public void EveryMemoOfThePropertyBlockIsResetWhereTheBlockIsCleared()
        {
            Assert.That(MemosNotResetWithTheBlock(RendererCode()), Is.Empty);
        }

        [Test]
        public void MemoCheckRejectsAMemoLeftStale()
        {
            // _LodLevels' memo kept after the clear: the level count is never sent again (cracked seams).
            string old = "int _sentLevelCount; GraphicsBuffer _boundSnowDepth;\n" +
                         "public void ReleaseGpuResources() { _props?.Clear(); _boundSnowDepth = null; }\n" +
                         "void PushLevels() { if (count != _sentLevelCount) { SetVector(Ids.LodLevels, v); _sentLevelCount = count; } }";
            Assert.That(MemosNotResetWithTheBlock(old), Is.EqualTo(new[] { "_sentLevelCount is not reset in ReleaseGpuResources, which clears the property block" }));
            string twice = "void A() { _props.Clear(); _sent = default; } void B() { _props?.Clear(); }";
            Assert.That(MemosNotResetWithTheBlock(twice), Does.Contain("the property block is cleared in 2 places, not one"));
            Assert.That(MemosNotResetWithTheBlock("void ClearPropertyBlock() { _props?.Clear(); _sent = default; } void P() { if (_sent.levelCount != n) _sent.levelCount = n; }"), Is.Empty);
            string unforgotten = "void ClearPropertyBlock() { _props?.Clear(); } void U() { if (_state.BindNoiseCells(table)) SetBuffer(id, table); }";
            Assert.That(MemosNotResetWithTheBlock(unforgotten), Is.EqualTo(new[] { "ClearPropertyBlock clears the property block without _state.Forget(), which resets the bindings FrameState remembers" }));
            Assert.That(MemosNotResetWithTheBlock(unforgotten.Replace("_props?.Clear();", "_props?.Clear(); _state.Forget();")), Is.Empty);
        }

        // ---- 2. The draw's bounds hold what the shader's tile culling keeps -----------------------

        static string ShaderFunction(string file, string name) =>
            Body(StripComments(File.ReadAllText(PackageRoot.Combine("Shaders", "Terrain", file))), name);

        /// <summary>
        /// The height margins the shader's <c>TileCulled</c> adds to a tile's box as named terms
        /// (<c>hi.y += F()</c>) that the renderer's <c>WorldBounds</c> does not add: Unity culls the
        /// whole draw by those bounds, so a tile the shader keeps outside them vanishes.
        /// </summary>
        internal static List<string> CullMarginsMissingFromBounds(string tileCulled, string worldBounds)
        {
            var terms = Regex.Matches(tileCulled, @"hi\.y\s*\+=\s*(\w+)\s*\(\s*\)").Select(m => m.Groups[1].Value).Distinct();
            return terms.Where(t => !Regex.IsMatch(worldBounds, $@"\b{t}\s*\(\s*\)")).ToList();
        }

        [Test]
        public void WorldBoundsHoldTheSnowCapTheTileCullingAdds()
        {
            string tileCulled = ShaderFunction("TileFactors.hlsl", "TileCulled");
            Assert.That(tileCulled, Does.Contain("SnowDepthCap()"), "the shader's culling box grows by the snow cap");
            Assert.That(CullMarginsMissingFromBounds(tileCulled, Body(RendererCode(), "WorldBounds")), Is.Empty,
                "height margins of TileCulled that RenderParams.worldBounds lacks");
        }

        [Test]
        public void BoundsCheckRejectsBoundsWithoutTheCap()
        {
            string culled = "{ hi.y += margin; #if defined(GT_SNOW)\n hi.y += SnowDepthCap();\n#endif }";
            string old = "{ float noise = NoiseMargin(); Vector3 max = new Vector3(c, _gridMaxZ + noise, h); }";
            Assert.That(CullMarginsMissingFromBounds(culled, old), Is.EqualTo(new[] { "SnowDepthCap" }));
            Assert.That(CullMarginsMissingFromBounds(culled, "{ max.y += SnowDepthCap(); }"), Is.Empty);
        }

        // ---- 3. The draw mode follows the SubShader Unity picks -----------------------------------

        /// <summary>
        /// What Unity's choice of SubShader depends on besides the material and its shader, which the
        /// cached draw mode must be keyed on: the shader LOD (global and per shader) and the render
        /// pipeline (the SubShaders' RenderPipeline tags).
        /// </summary>
        internal static readonly string[] SubShaderInputs = { "Shader.globalMaximumLOD", "maximumLOD", "GraphicsSettings.currentRenderPipeline" };

        internal static List<string> DrawModeKeyMisses(string readDrawMode) =>
            SubShaderInputs.Where(i => !Regex.IsMatch(readDrawMode, $@"(?<![\w]){Regex.Escape(i)}\b")).ToList();

        [Test]
        public void DrawModeIsReadAgainWhenTheActiveSubShaderCanChange()
        {
            string code = RendererCode();
            string read = Body(code, "ReadDrawMode");
            Assert.That(read, Does.Contain("GetTag"), "ReadDrawMode reads the SubShader's tag");
            // With the types it keys the cache by (a struct of the renderer's named in it).
            foreach (Match t in Regex.Matches(code, @"\b(?:struct|class)\s+(\w+)"))
                if (Regex.IsMatch(read, $@"\b{t.Groups[1].Value}\b")) read += Body(code, t.Groups[1].Value);
            Assert.That(DrawModeKeyMisses(read), Is.Empty, "inputs of Unity's SubShader choice the cached draw mode ignores");
        }

        [Test]
        public void DrawModeCheckRejectsACachePerMaterialAndShader()
        {
            string old = "{ if (material == _drawModeMaterial && material.shader == _drawModeShader) return _drawFallback; string tag = material.GetTag(DrawTag, false, \"\"); }";
            Assert.That(DrawModeKeyMisses(old), Is.EqualTo(SubShaderInputs));
        }

        // ---- 4. With the levels, each camera keeps its own range origin --------------------------

        static string PlannerCode() => StripComments(File.ReadAllText(PackageRoot.Combine("Runtime", "Core", "Terrain", "FramePlanner.cs")));

        /// <summary>
        /// Why the plan would re-snap the range origin per camera with Horizon levels (the origin
        /// follows each camera's finest level): Core's <c>Plan</c> must take the tracker of the camera
        /// drawn (CameraRangeOrigins) with the levels and the one range's without, and the renderer
        /// must name the camera (its instance ID). FramePlannerTests checks the rule itself.
        /// </summary>
        internal static List<string> SharedOriginProblems(string renderer, string planner)
        {
            string plan = Body(planner, "Plan") ?? "";
            var p = new List<string>();
            if (!Regex.IsMatch(plan, @"cameraOrigins\.For\s*\(\s*f\.camera\s*\)")) p.Add("Plan takes no tracker per camera");
            if (!Regex.IsMatch(plan, @"levels\s*\?[^;]*cameraOrigins[^;]*:\s*s\.rangeOrigin\s*;")) p.Add("Plan does not keep the one range's tracker without the levels");
            if (!Regex.IsMatch(renderer, @"\bcamera\s*=\s*cam\.GetInstanceID\(\)")) p.Add("the renderer does not name the camera drawn");
            return p;
        }

        [Test]
        public void WithTheLevelsEachCameraKeepsItsOwnOrigin()
        {
            Assert.That(SharedOriginProblems(RendererCode(), PlannerCode()), Is.Empty);
        }

        [Test]
        public void OriginCheckRejectsOneTrackerForEveryCamera()
        {
            string old = "public static FrameChange Plan(FrameState s, in FrameInputs f) { RangeOriginTracker tracker = s.rangeOrigin; bool moved = tracker.Update(f.range); }";
            Assert.That(SharedOriginProblems("FrameInputs FrameInputsFor(Camera cam) { return new FrameInputs { range = _range }; }", old), Is.EqualTo(new[]
            {
                "Plan takes no tracker per camera", "Plan does not keep the one range's tracker without the levels", "the renderer does not name the camera drawn",
            }));
        }

        // ---- 5. The per-frame rules are Core's, not the renderer's memos ---------------------------

        /// <summary>
        /// Ways the renderer would keep per-frame rules of its own again: a dirty flag (the rules
        /// were 11 writes of <c>_settingsDirty = true</c>), or a Prepare that does not send
        /// <see cref="FramePlanner"/>'s plan (FramePlannerTests checks the rules in dotnet test).
        /// </summary>
        internal static List<string> PerFrameRulesOutsideThePlanner(string code)
        {
            var p = Regex.Matches(code, @"\bbool\s+(_\w*[Dd]irty)\b").Select(m => $"dirty flag {m.Groups[1].Value}").Distinct().ToList();
            if (!Regex.IsMatch(Body(code, "Prepare") ?? "", @"FramePlanner\.Plan\s*\(\s*_\w+\s*,")) p.Add("Prepare does not plan the frame with FramePlanner.Plan");
            return p;
        }

        [Test]
        public void TheRendererSendsThePlannersPlanAndKeepsNoDirtyFlags()
        {
            Assert.That(PerFrameRulesOutsideThePlanner(RendererCode()), Is.Empty);
        }

        [Test]
        public void PlannerCheckRejectsTheDirtyFlags()
        {
            string old = "bool _settingsDirty = true;\nbool _frameDirty = true;\nbool Prepare(Camera cam = null) { if (_settingsDirty) { PushSettings(fallback); _settingsDirty = false; } else PushRange(); }";
            Assert.That(PerFrameRulesOutsideThePlanner(old), Is.EqualTo(new[]
            {
                "dirty flag _settingsDirty", "dirty flag _frameDirty", "Prepare does not plan the frame with FramePlanner.Plan",
            }));
        }

        // ---- 7. No structured buffer on a device that cannot make one -----------------------------

        /// <summary>
        /// Problems with the device check in <c>Prepare</c>: Unity's GraphicsBuffer constructor throws
        /// for a Structured target when <c>SystemInfo.supportsComputeShaders</c> is false, so the check
        /// must come before the upload (the first buffer made) and be made and logged once, not from
        /// every camera of every frame.
        /// </summary>
        internal static List<string> DeviceCheckProblems(string code)
        {
            var problems = new List<string>();
            string prepare = Body(code, "Prepare") ?? "";
            int upload = prepare.IndexOf("EnsureUploaded(");
            string checkName = Regex.Matches(prepare, @"!\s*(\w+)\s*\(\s*\)").Cast<Match>()
                .Select(m => m.Groups[1].Value).FirstOrDefault(n => (Body(code, n) ?? "").Contains("SystemInfo.supportsComputeShaders"));
            if (checkName == null) { problems.Add("Prepare calls no check of SystemInfo.supportsComputeShaders"); return problems; }
            if (prepare.IndexOf(checkName + "(") > upload) problems.Add($"{checkName} comes after EnsureUploaded");
            string body = Body(code, checkName);
            if (!Regex.IsMatch(code, @"static\s+\w+\??\s+s_\w+")) problems.Add("no static memo: the check is not made once");
            if (!body.Contains("Debug.Log")) problems.Add($"{checkName} logs nothing");
            return problems;
        }

        [Test]
        public void DeviceWithoutComputeIsToldOnceBeforeAnyStructuredBuffer()
        {
            string code = RendererCode();
            Assert.That(code, Does.Contain("GraphicsBuffer.Target.Structured"), "the renderer makes structured buffers");
            Assert.That(DeviceCheckProblems(code), Is.Empty);
        }

        /// <summary>
        /// GraphicsBuffer's constructor throws ArgumentException over SystemInfo.maxGraphicsBufferSize (2022.3,
        /// GraphicsBuffer.bindings.cs): the upload turns it into its error, logged once, not an exception every frame.
        /// </summary>
        [Test]
        public void AGridTooLargeForTheDeviceIsToldNotThrown()
        {
            string upload = File.ReadAllText(PackageRoot.Combine("Runtime", "TerrainGpuBuffers.cs"));
            Assert.That(UncaughtBufferCreation(upload), Is.False, "TerrainGpuBuffers.Upload");
            string old = "internal string Upload(PatchGrid g) { try { records = Pack(g); } catch (ArgumentException e) { return e.Message; }\n" +
                         "ControlPoints = new GraphicsBuffer(GraphicsBuffer.Target.Structured, n, 320); ControlPoints.SetData(records); return null; }";
            Assert.That(UncaughtBufferCreation(old), Is.True, "the unfixed upload");
        }

        static bool UncaughtBufferCreation(string code)
        {
            string body = code.Substring(code.IndexOf("string Upload(", StringComparison.Ordinal));
            int end = body.IndexOf("\n        }", StringComparison.Ordinal);   // the method's closing brace
            if (end > 0) body = body.Substring(0, end);
            int made = body.LastIndexOf("new GraphicsBuffer(", StringComparison.Ordinal);
            int caught = body.IndexOf("catch (ArgumentException e) { ReleaseGrid(); return e.Message; }", Math.Max(made, 0), StringComparison.Ordinal);
            return made < 0 || caught < 0;
        }

        /// <summary>
        /// The cache's verdict runs for every camera every frame; with a Cache Shader that lacks a kernel its
        /// reason names the shader, and Object.name makes a new string on each call (2022.3,
        /// UnityEngineObject.bindings.cs): the reason is built once per refused shader, not per frame.
        /// </summary>
        [Test]
        public void TheMissingKernelReasonIsNotBuiltEveryFrame()
        {
            string code = StripComments(File.ReadAllText(PackageRoot.Combine("Runtime", "VertexCachePass.cs")));
            Assert.That(BuildsNamedStringEachCall(Body(code, "UnavailableReason")), Is.False, "VertexCachePass.UnavailableReason");
            string old = "{ if (!FindKernels(shader, out string missing)) return $\"the Cache Shader '{shader.name}' has no kernel '{missing}'\"; return null; }";
            Assert.That(BuildsNamedStringEachCall(old), Is.True, "the unfixed verdict");
        }

        /// <summary>
        /// The levels' factor kernels write a buffer per camera: HDRP raises every camera's
        /// beginCameraRendering (where the renderer dispatches and draws) before it executes any camera's
        /// draws (HDRenderPipeline.Render: the culling loop, then the render requests), so one shared buffer
        /// would hold the last camera's factors when the first draws. Each camera binds its own buffer, and
        /// the kernels must be supported on this device, not only present (ComputeShader.IsSupported).
        /// </summary>
        [Test]
        public void TheLevelsFactorKernelsWriteABufferPerCamera()
        {
            string code = StripComments(File.ReadAllText(PackageRoot.Combine("Runtime", "LevelFactorPass.cs")));
            string update = Body(code, "UpdateFrame");
            Assert.That(update, Does.Contain("FactorsOf(cam, patches)"), "the camera's own buffer");
            Assert.That(Body(code, "FactorsOf"), Does.Contain("EvictCameras(idleToo: _byCamera.Count >= CameraRangeOrigins.MaxCameras)").And.Not.Contain("ReleaseCameraBuffers()"),
                "a new camera evicts, live cameras only past the camera limit and only idle ones: one a camera drew with this frame may still be read by a queued draw");
            Assert.That(Body(code, "EvictCameras"), Does.Contain("camera == null || (idleToo && e.Value.frame != Time.frameCount)"),
                "destroyed cameras' buffers go when a camera is added; live ones only when idle at the camera limit");
            Assert.That(update, Does.Contain("Bind(props, f.buffer)").And.Contain("Dispatch(r, cam, state, gpu, tiles, f)"), "bound and written: the same camera's buffer");
            Assert.That(code, Does.Not.Match(@"\bGraphicsBuffer\s+_factors\b"), "no buffer shared by every camera");
            string find = Body(code, "FindKernels");
            foreach (string kernel in new[] { "LodFactorPiecesKernel", "LodFactorSeamsKernel", "LodVertexSlotsKernel", "LodCacheVerticesKernel" })
                Assert.That(find, Does.Contain($"FindKernel(shader, ShaderIds.{kernel})"), kernel + " found through FindKernel");
            Assert.That(Body(code, "FindKernel"), Does.Contain("IsSupported(kernel) ? kernel : -1"), "a kernel that did not compile for the platform is not dispatched");
            // The levels' vertex records: the camera's own buffer too, bound for its draw, its count sent.
            Assert.That(update, Does.Contain("EnsureRecords(f, state").And.Contain("DispatchCache(state, tiles, f)").And.Contain("BindRecords(props, cache ? f.records"), "the camera's own records buffer");
            Assert.That(code, Does.Not.Match(@"\bGraphicsBuffer\s+_records\b"), "no records buffer shared by every camera");
        }

        /// <summary>
        /// Every global the levels' kernels read through LodCameraComputeAdapter.hlsl (the camera's
        /// object-to-clip and pixels, the terrain's world-to-object for the cached normals) is set by
        /// LevelFactorPass.Dispatch: Unity leaves an unset compute global at zero or at what another
        /// renderer last set on the shared asset, which the rig (its own adapter) cannot show.
        /// </summary>
        [Test]
        public void TheLevelsKernelsGetEveryCameraGlobalTheyRead()
        {
            string adapter = File.ReadAllText(PackageRoot.Combine("Shaders", "Pipelines", "LodCameraComputeAdapter.hlsl"));
            var globals = Regex.Matches(adapter, @"(?m)^float4(?:x4)?\s+(_\w+)\s*;").Select(m => m.Groups[1].Value).ToList();
            Assert.That(globals, Has.Count.GreaterThanOrEqualTo(3), "globals declared by the adapter");
            string ids = File.ReadAllText(PackageRoot.Combine("Runtime", "ShaderIds.cs"));
            string dispatch = Body(StripComments(File.ReadAllText(PackageRoot.Combine("Runtime", "LevelFactorPass.cs"))), "Dispatch");
            foreach (string name in globals)
            {
                Match id = Regex.Match(ids, @"(\w+)\s*=\s*Shader\.PropertyToID\(""" + Regex.Escape(name) + @"""\)");
                Assert.That(id.Success, Is.True, name + " has a ShaderIds field");
                Assert.That(dispatch, Does.Match(@"shader\.Set\w+\(ShaderIds\." + id.Groups[1].Value + @"\b"), $"LevelFactorPass.Dispatch sets {name} (ShaderIds.{id.Groups[1].Value})");
            }
        }

        static bool BuildsNamedStringEachCall(string body) => body == null || Regex.IsMatch(body, @"\$""[^""]*\{\w+\.name\}");

        [Test]
        public void DeviceCheckRejectsAnUncheckedUpload()
        {
            string old = "bool Prepare(Camera cam = null) { if (material == null) return false; if (!EnsureUploaded()) return false; }";
            Assert.That(DeviceCheckProblems(old), Is.EqualTo(new[] { "Prepare calls no check of SystemInfo.supportsComputeShaders" }));
            string late = "static string s_DeviceError; bool Prepare(Camera cam = null) { if (!EnsureUploaded()) return false; if (!DeviceCanDraw()) return false; }\n" +
                          "bool DeviceCanDraw() { return SystemInfo.supportsComputeShaders; }";
            Assert.That(DeviceCheckProblems(late), Is.EqualTo(new[] { "DeviceCanDraw comes after EnsureUploaded", "DeviceCanDraw logs nothing" }));
        }
    }
}
