<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name>celform::app::Cli</name>
    <message>
        <source>usage: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Creates a project from a mesh file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mesh file (OBJ, PLY, STL, OFF, glTF, GLB).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference drawing to embed (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--out is required
usage: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning: %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prints what a project holds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file (.celform).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print machine-readable JSON.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project: %1 (format %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model: %1, %2 vertices, %3 triangles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawings: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Key viewpoints: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: celform [PROJECT] [--screenshot FILE.png]
       celform new MESH --out P.celform [--drawing IMAGE]...
       celform info P.celform [--json]
       celform --version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>celform: out of memory</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::app::MainWindow</name>
    <message>
        <source>Not enough memory.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autosaved a recovery copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;Opened project&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every edit of the project; click an entry to go back to it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>History</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New from Mesh…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start a new project on a base model (OBJ, PLY, STL, OFF, glTF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a Celform project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import &amp;Mesh…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replace the base model by a mesh file with the same vertex order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import &amp;Drawing…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a reference drawing (PNG, JPEG, TIFF, EXR, PSD, SVG) to the model sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit Celform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the selected drawing or key viewpoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Frame All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the whole model in the viewport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch between perspective and orthographic projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Celform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version and licence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Celform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Celform %1&lt;/h3&gt;&lt;p&gt;View-dependent models, shaped highlights and stereo-aware toon rendering for cel animation.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Qt version and licence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Navigation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mouse and keyboard navigation in the viewport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Viewport navigation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + left drag&lt;/b&gt;, &lt;b&gt;middle drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + middle drag&lt;/b&gt;, &lt;b&gt;Shift + middle drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + right drag&lt;/b&gt;, &lt;b&gt;Ctrl + middle drag&lt;/b&gt;, &lt;b&gt;wheel&lt;/b&gt;&lt;/td&gt;&lt;td&gt;dolly&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame all&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;front view&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;perspective / orthographic&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1[*] — Celform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No base model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 vertices · %2 triangles · %3 drawings · %4 keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Celform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 loaded with warnings: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not a project, mesh or image file Celform can read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loaded %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Added drawing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Celform projects (*.celform)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project “%1” has unsaved changes. Save them first?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Project from Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Drawings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No recent projects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an untitled project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Celform did not close normally. A recovery copy of %1 from %2 was found.

Recover it now?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep for Later</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Discard…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recovered %1; save it to keep it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard recovery copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the recovery copy of %1 for good?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::model::Document</name>
    <message>
        <source>has %1 vertices, but the key deformations use vertex %2; a replacement base model needs the same vertex count and order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replace Base Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add Drawing “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Drawing “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename Drawing to “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Drawing Opacity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Align Drawing “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add Key “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Key “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename Key to “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable Key “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable Key “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Blend Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Look</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::model::ImageIo</name>
    <message>
        <source>not a valid SVG drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the SVG drawing has no size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the SVG drawing is too large</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>images of type &quot;%1&quot; cannot be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a temporary copy of the image cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the image cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the image has no pixels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the image is too large (%1 x %2 pixels)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the image data is damaged or truncated: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown image format &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::model::MeshIo</name>
    <message>
        <source>the file does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1 refers to vertex %2, but the file has %3 vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 face with fewer than three corners ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n faces with fewer than three corners ignored</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>the header announces %1 vertices and %2 faces, more than the file holds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends early, while reading %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: expected %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a vertex coordinate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a vertex index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a property value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex %1 has a coordinate that is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only three-dimensional OFF files are supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary OFF files are not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not an OFF file (it does not start with &quot;OFF&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the header has a negative vertex or face count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1 has an invalid corner count %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLY header line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a PLY file (it does not start with &quot;ply&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PLY header has no end_header line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>incomplete format line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown format &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid element line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>property before any element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown property type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid property line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown keyword &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PLY header has no format line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is truncated: it ends inside the &quot;%1&quot; element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the face element has no vertex_indices list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element &quot;%1&quot; row %2 has an invalid list length %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the PLY file has no vertex element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the vertex element lacks an x, y or z property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: vertex %2 has a coordinate that is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a readable OBJ file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1 is incomplete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1 refers to texture coordinate %2, but the file has %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>some materials could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the scene has more vertices than Celform can hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a readable %1 file: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 point or line ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n points or lines ignored</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>the file contains no vertices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file contains no faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the mesh is unusable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 hole</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n holes</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n components</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>1 non-manifold edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n non-manifold edges</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>1 edge with inconsistent face orientation</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n edges with inconsistent face orientation</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>1 degenerate face</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n degenerate faces</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>, </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown mesh format &quot;%1&quot;; use one of: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Meshes (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write &quot;%1&quot; files; use .obj or .ply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file cannot be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::model::ProjectFile</name>
    <message>
        <source>could not be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is damaged: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the entry “%1” is missing or has the wrong type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the entry “%1” is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the count “%1” is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the entry “%1” has the unknown value “%2”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the data block “%1” is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the data block “%1” lies outside the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the data block “%1” has %2 bytes instead of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the data block “%1” fails its checksum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a texture coordinate index is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face set “%1” refers to a face out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a face material index is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the base model is invalid (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key “%1” has a vertex index out of range or out of order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key “%1” has a non-finite offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an object id is not below next_id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not be opened for writing: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not be saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>could not be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is not a Celform project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is truncated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>was written by a newer version of Celform (file format %1; this version reads up to %2). Please update Celform to open it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is damaged: the format version is 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is truncated or damaged: its end marker is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is damaged: its table of contents lies outside the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is damaged: its table of contents fails its checksum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the entry “%1” is not a 3D vector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the entry “%1” is not finite</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::views::PropertiesPanel</name>
    <message>
        <source>Selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name shown in the scene tree and used by the command line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opacity of the drawing over the model in the viewport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Opacity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Enabled in the blend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A disabled key keeps its deformation but takes no part in the blend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View-dependent blend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sharpness α of the blend weights: 1 blends linearly across the viewing sphere; larger values hold each key longer and switch faster near facet centres.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Sharpness α:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dummy keys (base model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cosine falloff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Squared cosine falloff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How views far from every key are shaped: dummy keys return to the base model along the main axes; cosine modes fade each key out with the angle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Unspecified regions:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 × %2 pixels, %3, %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>camera aligned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>camera not aligned yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Key viewpoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>frame %1: %n vertices moved</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Direction (%1, %2, %3)
%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No deformation yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
%2 vertices, %3 triangles
Size %4 × %5 × %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No base model. Import a mesh with File &gt; Import Mesh, or drop a mesh file on the window.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::views::ScenePanel</name>
    <message>
        <source>The base model, the reference drawings and the key viewpoints of the project.
Double-click or press F2 to rename; Delete removes; the check box disables a key.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 3D model that the key deformations change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Base model: none (File &gt; Import Mesh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference drawings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model sheet: hand-drawn views of the character</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 × %2 px, %3%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, aligned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, not aligned yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Key viewpoints (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Key deformations, each seen from its key viewpoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction (%1, %2, %3)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>celform::views::Viewport</name>
    <message>
        <source>3D viewport</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;The 3D view of the model.&lt;/p&gt;&lt;p&gt;Alt+left drag or middle drag: orbit. Alt+middle drag or Shift+middle drag: pan. Alt+right drag, Ctrl+middle drag or the mouse wheel: dolly. F: frame the model. Home: front view.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Celform: view-dependent models and cartoon looks for cel animation.
Sub-commands (celform new, info, ...) run without the editor: see celform --help.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project (.celform) or mesh file to open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open, render once, save a PNG of the main window to FILE and quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only one project can be opened</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
