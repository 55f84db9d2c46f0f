using System;
using System.Reflection;
using UnityEngine;

namespace GregoryTerrain.Samples.TerrainFlyover
{
    /// <summary>
    /// Sample: one sun that looks right in Built-in, URP and HDRP. Built-in and URP take the Light's
    /// unitless intensity; HDRP reads a directional light's intensity as illuminance in lux and shows it
    /// through the camera's exposure, so under HDRP in Play Mode this sets the sun to <see cref="hdrpLux"/> and adds a
    /// global Volume, never saved, with a fixed exposure of <see cref="hdrpExposure"/> EV100. The HDRP
    /// types are reached by name (the sample must compile and open without HDRP): no HDRP component is
    /// stored in the scene, so Built-in and URP projects see no missing script.
    /// </summary>
    [ExecuteAlways, RequireComponent(typeof(Light))]
    [AddComponentMenu("Gregory Terrain/Samples/Sample Sun")]
    public sealed class SampleSun : MonoBehaviour
    {
        const string HdrpTag = "HDRenderPipeline";   // Shader.globalRenderPipeline while HDRP renders

        [Tooltip("Sun intensity in Built-in and URP (their unitless light intensity).")]
        [SerializeField, Min(0f)] float intensity = 1.2f;

        [Tooltip("Sun illuminance in HDRP, in lux. A clear midday sun is about 100000 lux.")]
        [SerializeField, Min(0f)] float hdrpLux = 100000f;

        [Tooltip("HDRP fixed exposure in EV100 for the sun above. 15 suits a 100000 lux sun (the sunny-16 rule: f/16 at 1/100 s, ISO 100).")]
        [SerializeField, Range(-10f, 20f)] float hdrpExposure = 15f;

        (bool hdrp, bool playing)? _applied;
        GameObject _exposureVolume;
        ScriptableObject _exposureProfile;

        void OnEnable() => Apply();

        void OnValidate() => _applied = null;   // re-applied on the next Update (OnValidate must not create objects)

        // HDRP sets the pipeline tag when it first renders, which may follow OnEnable: look again each frame
        // (one string compare) and apply only when the pipeline changed.
        void Update() => Apply();

        void OnDisable()
        {
            _applied = null;
            RemoveExposureVolume();
        }

        void RemoveExposureVolume()
        {
            if (_exposureVolume != null) DestroyImmediate(_exposureVolume);
            if (_exposureProfile != null) DestroyImmediate(_exposureProfile);
            _exposureVolume = null;
            _exposureProfile = null;
        }

        // In Edit Mode the Light keeps its saved intensity (a write would change the scene as it opens);
        // under HDRP the unsaved exposure is then lowered by the ratio of that intensity to hdrpLux,
        // so the Scene view shows what Play Mode shows.
        void Apply()
        {
            bool hdrp = Shader.globalRenderPipeline == HdrpTag, playing = Application.isPlaying;
            if (_applied == (hdrp, playing)) return;
            _applied = (hdrp, playing);
            var sun = GetComponent<Light>();
            if (!hdrp)
            {
                if (playing) sun.intensity = intensity;
                RemoveExposureVolume();
                return;
            }
            float ev100 = hdrpExposure;
            if (playing)
            {
                sun.intensity = hdrpLux;
                // HDRP keeps the intensity it uses on its additional light data when the light has one.
                Component hdLight = gameObject.GetComponent("HDAdditionalLightData");
                if (hdLight != null) SetProperty(hdLight, "intensity", hdrpLux);
            }
            else if (sun.intensity > 0f && hdrpLux > 0f)
                ev100 -= Mathf.Log(hdrpLux / sun.intensity, 2f);
            RemoveExposureVolume();
            _exposureVolume = CreateExposureVolume(ev100, out _exposureProfile);
        }

        /// <summary>
        /// A hidden, unsaved global Volume whose profile holds HDRP's Exposure in Fixed mode. Returns null,
        /// with a warning naming what is missing, if HDRP's types are not as expected.
        /// </summary>
        static GameObject CreateExposureVolume(float ev100, out ScriptableObject profile)
        {
            profile = null;
            Type volumeType = Type.GetType("UnityEngine.Rendering.Volume, Unity.RenderPipelines.Core.Runtime");
            Type profileType = Type.GetType("UnityEngine.Rendering.VolumeProfile, Unity.RenderPipelines.Core.Runtime");
            Type exposureType = Type.GetType("UnityEngine.Rendering.HighDefinition.Exposure, Unity.RenderPipelines.HighDefinition.Runtime");
            MethodInfo add = profileType?.GetMethod("Add", new[] { typeof(Type), typeof(bool) });
            if (volumeType == null || exposureType == null || add == null)
            {
                Debug.LogWarning("SampleSun: HDRP's Volume, VolumeProfile.Add(Type, bool) or Exposure type was not found; the sun keeps HDRP's default exposure.", null);
                return null;
            }
            var go = new GameObject("Sample Exposure (not saved)") { hideFlags = HideFlags.HideAndDontSave };
            profile = ScriptableObject.CreateInstance(profileType);
            profile.hideFlags = HideFlags.HideAndDontSave;
            object exposure = add.Invoke(profile, new object[] { exposureType, true });   // overrides = true: every parameter overridden
            bool ok = SetParameter(exposure, "mode", 0)                  // ExposureMode.Fixed
                      && SetParameter(exposure, "fixedExposure", ev100);
            Component volume = go.AddComponent(volumeType);
            ok &= SetField(volume, "isGlobal", true) && SetField(volume, "sharedProfile", profile);
            if (!ok) Debug.LogWarning("SampleSun: HDRP's Exposure or Volume members were not as expected; the sun may show with HDRP's default exposure.", null);
            return go;
        }

        static bool SetParameter(object component, string field, object value)
        {
            object parameter = component?.GetType().GetField(field)?.GetValue(component);
            PropertyInfo p = parameter?.GetType().GetProperty("value");
            if (p == null) return false;
            p.SetValue(parameter, p.PropertyType.IsEnum ? Enum.ToObject(p.PropertyType, value) : Convert.ChangeType(value, p.PropertyType));
            return true;
        }

        static bool SetField(object target, string name, object value)
        {
            FieldInfo f = target?.GetType().GetField(name);
            if (f == null) return false;
            f.SetValue(target, value);
            return true;
        }

        static void SetProperty(object target, string name, float value) =>
            target.GetType().GetProperty(name)?.SetValue(target, value);
    }
}
