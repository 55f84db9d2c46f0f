#!/usr/bin/env python3
"""Writes a .meta for every file and folder Unity imports that has none.

GUIDs are derived from the package name and the path (MD5), so re-running never changes an existing
GUID and two checkouts agree. Existing .meta files are never touched. Folders whose names end in '~'
and dot-files are not imported by Unity and get no .meta. Samples~ is the exception: its contents are
copied into a user's Assets folder on import, so they need .meta files of their own.
"""
import hashlib, os, sys

PKG = "com.gregoryterrain.tessellation"
ROOT_FILES = ["package.json", "README.md", "CHANGELOG.md", "LICENSE.md"]
IMPORTED_DIRS = ["Runtime", "Shaders", "Editor", "Tests"]
SAMPLE_DIR = "Samples~"

IMPORTERS = {
    ".cs": "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n",
    ".asmdef": "AssemblyDefinitionImporter:\n  externalObjects: {}\n",
    ".shader": "ShaderImporter:\n  externalObjects: {}\n  defaultTextures: []\n  nonModifiableTextures: []\n",
    ".hlsl": "ShaderIncludeImporter:\n  externalObjects: {}\n",
    ".compute": "ComputeShaderImporter:\n  externalObjects: {}\n  currentAPIMask: 4\n  preprocessorOverride: 0\n",
    ".md": "TextScriptImporter:\n  externalObjects: {}\n",
    ".json": "TextScriptImporter:\n  externalObjects: {}\n",
    ".txt": "TextScriptImporter:\n  externalObjects: {}\n",
    ".unity": "DefaultImporter:\n  externalObjects: {}\n",
    ".mat": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 2100000\n",
    ".asset": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 11400000\n",
}
TAIL = "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"


def guid_for(rel):
    return hashlib.md5(f"{PKG}:{rel}".encode()).hexdigest()


def meta_text(rel, is_dir):
    head = f"fileFormatVersion: 2\nguid: {guid_for(rel)}\n"
    if is_dir:
        return head + "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + TAIL
    ext = os.path.splitext(rel)[1].lower()
    return head + IMPORTERS.get(ext, "DefaultImporter:\n  externalObjects: {}\n") + TAIL


def imported(root):
    for f in ROOT_FILES:
        if os.path.isfile(os.path.join(root, f)):
            yield f, False
    for top in IMPORTED_DIRS + [SAMPLE_DIR]:
        base = os.path.join(root, top)
        if not os.path.isdir(base):
            continue
        if top != SAMPLE_DIR:
            yield top, True
        for d, dirs, files in os.walk(base):
            dirs[:] = sorted(x for x in dirs if not x.endswith("~") and not x.startswith("."))
            for x in dirs:
                yield os.path.relpath(os.path.join(d, x), root), True
            for x in sorted(files):
                if x.endswith(".meta") or x.startswith("."):
                    continue
                yield os.path.relpath(os.path.join(d, x), root), False


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
    written = 0
    for rel, is_dir in imported(root):
        meta = os.path.join(root, rel + ".meta")
        if not os.path.exists(meta):
            with open(meta, "w", newline="\n") as fh:
                fh.write(meta_text(rel, is_dir))
            written += 1
            print(f"wrote {rel}.meta")
    print(f"{written} .meta files written")


if __name__ == "__main__":
    main()
