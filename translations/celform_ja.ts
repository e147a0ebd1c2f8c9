<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name>AnimationIo</name>
    <message>
        <source>%1 names accessor %2, which does not exist</source>
        <translation>%1 が存在しないアクセサー %2 を参照しています</translation>
    </message>
</context>
<context>
    <name>CameraPath</name>
    <message>
        <source>camera key %1 is at frame %2, beyond ±%3</source>
        <translation>カメラのキーフレーム %1 がフレーム %2 にあり、±%3 の範囲を超えています</translation>
    </message>
    <message>
        <source>camera keys are not in increasing frame order at frame %1</source>
        <translation>フレーム %1 でカメラのキーフレームがフレーム順に並んでいません</translation>
    </message>
    <message>
        <source>the camera key at frame %1 is not a usable camera</source>
        <translation>フレーム %1 のカメラのキーフレームは使用できるカメラではありません</translation>
    </message>
    <message>
        <source>a turntable needs 2 to %1 frames, not %2</source>
        <translation>ターンテーブルには 2～%1 フレームが必要です（%2 は無効です）</translation>
    </message>
    <message>
        <source>the turntable&apos;s frames leave the range ±%1</source>
        <translation>ターンテーブルのフレームが ±%1 の範囲を超えています</translation>
    </message>
    <message>
        <source>the turntable axis must be a finite, non-zero vector</source>
        <translation>ターンテーブルの軸は有限でゼロ以外のベクトルである必要があります</translation>
    </message>
    <message>
        <source>the elevation must lie strictly between -90 and 90 degrees</source>
        <translation>仰角は -90 度より大きく 90 度より小さい値である必要があります</translation>
    </message>
    <message>
        <source>the start angle must lie between -%1 and %1 degrees</source>
        <translation>開始角度は -%1～%1 度の範囲で指定してください</translation>
    </message>
</context>
<context>
    <name>Cli</name>
    <message>
        <source>--depth-threshold takes a fraction of the model&apos;s size in (0, 1], not “%1”</source>
        <translation>--depth-threshold にはモデルの大きさに対する割合 (0, 1] を指定します（“%1” ではありません）</translation>
    </message>
    <message>
        <source>--min-pixels takes a whole number of at least 1, not “%1”</source>
        <translation>--min-pixels には 1 以上の整数を指定します（“%1” ではありません）</translation>
    </message>
    <message>
        <source>has no key named “%1”</source>
        <translation>「%1」という名前のキーがありません</translation>
    </message>
    <message>
        <source>%1 takes on, off or a comma-separated list of silhouette, crease, border, material and ridge, not “%2”</source>
        <translation>%1 には on、off、または silhouette、crease、border、material、ridge をカンマ区切りで指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>has no drawing named “%1”</source>
        <translation>「%1」という名前の参照画がありません</translation>
    </message>
    <message>
        <source>--threshold takes auto or a number from 0 to 1, not “%1”</source>
        <translation>--threshold には auto または 0～1 の数値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--closing takes a radius from 0 to %1 pixels, not “%2”</source>
        <translation>--closing には 0～%1 ピクセルの半径を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>has no vertex %1 (the base model has %2 vertices)</source>
        <translation>頂点 %1 がありません（ベースモデルの頂点数は %2 です）</translation>
    </message>
    <message>
        <source>“%1” works on the project file: save the document first (Document.save(path))</source>
        <translation>“%1” はプロジェクトファイルに対して動作します。先にドキュメントを保存してください (Document.save(path))</translation>
    </message>
    <message>
        <source>warning: %1: a key named “%2” exists; the new key is named “%3”</source>
        <translation>警告: %1: “%2” という名前のキーがすでにあります。新しいキーの名前は “%3” です</translation>
    </message>
    <message>
        <source>frame %1: %2</source>
        <translation>フレーム %1: %2</translation>
    </message>
    <message>
        <source>a render to an array takes one frame (frame=F), not --frames</source>
        <translation>配列へのレンダリングは 1 フレーム (frame=F) のみです。--frames は使えません</translation>
    </message>
    <message>
        <source>has no base model</source>
        <translation>ベースモデルがありません</translation>
    </message>
</context>
<context>
    <name>DrawingOutline</name>
    <message>
        <source>the outline threshold must lie in 0 to 1 (or be negative for automatic), not %1</source>
        <translation>輪郭のしきい値は 0～1 の範囲（自動にする場合は負の値）で指定してください（%1 は無効です）</translation>
    </message>
    <message>
        <source>the closing radius must lie in 0 to %1 pixels, not %2</source>
        <translation>クロージング半径は 0～%1 ピクセルの範囲で指定してください（%2 は無効です）</translation>
    </message>
    <message>
        <source>the smallest figure kept must not be negative, not %1</source>
        <translation>残す図形の最小サイズに負の値は指定できません（%1 は無効です）</translation>
    </message>
</context>
<context>
    <name>LightTrack</name>
    <message>
        <source>the light&apos;s vector is not finite</source>
        <translation>ライトのベクトルが有限の値ではありません</translation>
    </message>
    <message>
        <source>a directional light needs a direction</source>
        <translation>平行光源には方向が必要です</translation>
    </message>
    <message>
        <source>light key frame %1 is out of range</source>
        <translation>ライトキーのフレーム %1 が範囲外です</translation>
    </message>
    <message>
        <source>light key frames are not strictly increasing (%1 after %2)</source>
        <translation>ライトキーのフレームが厳密に増加していません（%2 の後に %1）</translation>
    </message>
    <message>
        <source>light key at frame %1: %2</source>
        <translation>フレーム %1 のライトキー: %2</translation>
    </message>
</context>
<context>
    <name>Look</name>
    <message>
        <source>the subdivision level must be 0 to %1, not %2</source>
        <translation>細分化レベルは 0 から %1 の範囲で指定してください (%2 は使えません)</translation>
    </message>
    <message>
        <source>the viewport&apos;s subdivision level must be -1 (the render level) or 0 to %1, not %2</source>
        <translation>ビューポートの細分化レベルは -1 (レンダーのレベル) または 0 から %1 で指定してください (%2 は使えません)</translation>
    </message>
</context>
<context>
    <name>MeshIo</name>
    <message>
        <source>line %1: face %2 has the index %3, which is too large</source>
        <translation>%1 行目: 面 %2 のインデックス %3 が大きすぎます</translation>
    </message>
</context>
<context>
    <name>ProjectData</name>
    <message>
        <source>the face importance has %1 values for %2 faces</source>
        <translation>面の重要度の値が %1 個ありますが、面は %2 個です</translation>
    </message>
    <message>
        <source>a face importance lies outside 0 to 1</source>
        <translation>面の重要度に 0～1 の範囲外の値があります</translation>
    </message>
    <message>
        <source>the segment overrides have %1 labels for %2 faces</source>
        <translation>セグメントの上書きのラベルが %1 個ありますが、面は %2 個です</translation>
    </message>
    <message>
        <source>a segment override label is out of range</source>
        <translation>セグメントの上書きのラベルが範囲外です</translation>
    </message>
</context>
<context>
    <name>ProjectFile</name>
    <message>
        <source>the entry “%1” is not a 3 by 3 matrix</source>
        <translation>項目「%1」が 3×3 行列ではありません</translation>
    </message>
</context>
<context>
    <name>SceneTime</name>
    <message>
        <source>frames per second must lie in (0, %1], not %2</source>
        <translation>フレームレートは (0, %1] の範囲で指定してください（%2 は無効です）</translation>
    </message>
    <message>
        <source>the frame range must lie within ±%1</source>
        <translation>フレーム範囲は ±%1 の範囲内である必要があります</translation>
    </message>
    <message>
        <source>the frame range ends (%1) before it starts (%2)</source>
        <translation>フレーム範囲の終了（%1）が開始（%2）より前です</translation>
    </message>
</context>
<context>
    <name>app::Cli</name>
    <message>
        <source>celform: unknown sub-command “%1”</source>
        <translation>celform: 不明なサブコマンド「%1」です</translation>
    </message>
    <message>
        <source>missing arguments</source>
        <translation>引数が足りません</translation>
    </message>
    <message>
        <source>unexpected argument “%1”</source>
        <translation>予期しない引数「%1」です</translation>
    </message>
    <message>
        <source>celform %1 exited with code %2</source>
        <translation>celform %1 が終了コード %2 で終了しました</translation>
    </message>
</context>
<context>
    <name>celform::app::AnimationActions</name>
    <message>
        <source>Timeline</source>
        <translation>タイムライン</translation>
    </message>
    <message>
        <source>The scene&apos;s frames: range, frame rate, playback and every kind of key</source>
        <translation>シーンのフレーム: 範囲、フレームレート、再生、あらゆる種類のキーフレーム</translation>
    </message>
    <message>
        <source>&amp;Play / Pause</source>
        <translation>再生 / 一時停止(&amp;P)</translation>
    </message>
    <message>
        <source>Play the scene at its frame rate, or pause</source>
        <translation>シーンをそのフレームレートで再生、または一時停止します</translation>
    </message>
    <message>
        <source>&amp;Loop</source>
        <translation>ループ(&amp;L)</translation>
    </message>
    <message>
        <source>After the last frame of the range, play the first again</source>
        <translation>範囲の最後のフレームの後、最初のフレームから再び再生します</translation>
    </message>
    <message>
        <source>&amp;First Frame</source>
        <translation>最初のフレーム(&amp;F)</translation>
    </message>
    <message>
        <source>Go to the first frame of the range</source>
        <translation>範囲の最初のフレームに移動します</translation>
    </message>
    <message>
        <source>La&amp;st Frame</source>
        <translation>最後のフレーム(&amp;S)</translation>
    </message>
    <message>
        <source>Go to the last frame of the range</source>
        <translation>範囲の最後のフレームに移動します</translation>
    </message>
    <message>
        <source>P&amp;revious Frame</source>
        <translation>前のフレーム(&amp;R)</translation>
    </message>
    <message>
        <source>One frame back</source>
        <translation>1 フレーム戻ります</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>次のフレーム(&amp;N)</translation>
    </message>
    <message>
        <source>One frame on</source>
        <translation>1 フレーム進みます</translation>
    </message>
    <message>
        <source>Previous &amp;Key</source>
        <translation>前のキーフレーム(&amp;K)</translation>
    </message>
    <message>
        <source>Go to the previous frame holding a key of any kind</source>
        <translation>種類を問わずキーフレームのある前のフレームに移動します</translation>
    </message>
    <message>
        <source>Next K&amp;ey</source>
        <translation>次のキーフレーム(&amp;E)</translation>
    </message>
    <message>
        <source>Go to the next frame holding a key of any kind</source>
        <translation>種類を問わずキーフレームのある次のフレームに移動します</translation>
    </message>
    <message>
        <source>Look Through &amp;Shot Camera</source>
        <translation>ショットカメラから見る(&amp;S)</translation>
    </message>
    <message>
        <source>The main view follows the camera path at the current frame; turning the view with the mouse leaves it</source>
        <translation>メインビューが現在のフレームのカメラパスに従います。マウスで視点を回すと解除されます</translation>
    </message>
    <message>
        <source>&amp;Observer Layout</source>
        <translation>観察ビューのレイアウト(&amp;O)</translation>
    </message>
    <message>
        <source>Show the Observer beside the main view: the view-dependent model as the shot camera sees it, the camera path and the camera, from a fixed vantage point</source>
        <translation>メインビューの横に観察ビューを表示します: ショットカメラから見た視点依存モデル、カメラパス、カメラを固定の視点から表示します</translation>
    </message>
    <message>
        <source>&amp;Key Camera</source>
        <translation>カメラのキーフレームを設定(&amp;K)</translation>
    </message>
    <message>
        <source>Key the current view as the shot camera at the current frame</source>
        <translation>現在の視点を現在のフレームのショットカメラとしてキーフレームに設定します</translation>
    </message>
    <message>
        <source>Camera keyed at frame %1</source>
        <translation>フレーム %1 にカメラのキーフレームを設定しました</translation>
    </message>
    <message>
        <source>&amp;Remove Camera Key</source>
        <translation>カメラのキーフレームを削除(&amp;R)</translation>
    </message>
    <message>
        <source>Remove the camera key at the current frame</source>
        <translation>現在のフレームにあるカメラのキーフレームを削除します</translation>
    </message>
    <message>
        <source>&amp;Clear Camera Path</source>
        <translation>カメラパスを消去(&amp;C)</translation>
    </message>
    <message>
        <source>Remove every camera key: the render camera applies again</source>
        <translation>カメラのキーフレームをすべて削除します。再びレンダーカメラが使われます</translation>
    </message>
    <message>
        <source>&amp;Turntable…</source>
        <translation>ターンテーブル(&amp;T)…</translation>
    </message>
    <message>
        <source>Replace the camera path by one revolution around the model</source>
        <translation>カメラパスをモデルの周りを 1 周するパスで置き換えます</translation>
    </message>
    <message>
        <source>Turntable refused: %1</source>
        <translation>ターンテーブルを作成できません: %1</translation>
    </message>
    <message>
        <source>Play&amp;back</source>
        <translation>再生(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Camera</source>
        <translation>カメラ(&amp;C)</translation>
    </message>
</context>
<context>
    <name>celform::app::Cli</name>
    <message>
        <source>Mesh file (OBJ, PLY, STL, OFF, glTF, GLB).</source>
        <translation>メッシュファイル（OBJ、PLY、STL、OFF、glTF、GLB）。</translation>
    </message>
    <message>
        <source>Project file to write.</source>
        <translation>書き出すプロジェクトファイル。</translation>
    </message>
    <message>
        <source>Reference drawing to embed (repeatable).</source>
        <translation>埋め込む参照画（複数指定可）。</translation>
    </message>
    <message>
        <source>warning: %1: %2</source>
        <translation>警告: %1: %2</translation>
    </message>
    <message>
        <source>Prints what a project holds.</source>
        <translation>プロジェクトの内容を表示します。</translation>
    </message>
    <message>
        <source>Project file (.celform).</source>
        <translation>プロジェクトファイル（.celform）。</translation>
    </message>
    <message>
        <source>Print machine-readable JSON.</source>
        <translation>機械可読な JSON 形式で出力します。</translation>
    </message>
    <message>
        <source>Project: %1 (format %2)</source>
        <translation>プロジェクト: %1（フォーマット %2）</translation>
    </message>
    <message>
        <source>Base model: %1, %2 vertices, %3 triangles</source>
        <translation>ベースモデル: %1、頂点数 %2、三角形数 %3</translation>
    </message>
    <message>
        <source>Base model: none</source>
        <translation>ベースモデル: なし</translation>
    </message>
    <message>
        <source>Drawings: %1</source>
        <translation>参照画: %1</translation>
    </message>
    <message>
        <source>Key viewpoints: %1</source>
        <translation>キー視点: %1</translation>
    </message>
    <message>
        <source>celform: out of memory</source>
        <translation>celform: メモリが不足しています</translation>
    </message>
    <message>
        <source>--%1 needs a number, not “%2”</source>
        <translation>--%1 には数値を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>--%1 needs a whole number, not “%2”</source>
        <translation>--%1 には整数を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>Name of the new key.</source>
        <translation>新しいキーの名前。</translation>
    </message>
    <message>
        <source>Key deformation: a mesh with the base model&apos;s vertex count and order.</source>
        <translation>キー変形: ベースモデルと頂点数・頂点順序が同じメッシュ。</translation>
    </message>
    <message>
        <source>Start as a copy of the base model.</source>
        <translation>ベースモデルのコピーから開始します。</translation>
    </message>
    <message>
        <source>View direction from the model&apos;s centroid towards the eye.</source>
        <translation>視線方向（モデルの重心からカメラ位置に向かう方向）。</translation>
    </message>
    <message>
        <source>Camera position.</source>
        <translation>カメラ位置。</translation>
    </message>
    <message>
        <source>Point the camera looks at.</source>
        <translation>カメラの注視点。</translation>
    </message>
    <message>
        <source>Camera up vector.</source>
        <translation>カメラの上方向ベクトル。</translation>
    </message>
    <message>
        <source>Frame of the deformation (default 0).</source>
        <translation>変形のフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>Reference drawing to embed and link, aligned with the key&apos;s camera.</source>
        <translation>埋め込んでリンクする参照画（キーのカメラに位置合わせされます）。</translation>
    </message>
    <message>
        <source>Print the new key as JSON.</source>
        <translation>新しいキーを JSON 形式で出力します。</translation>
    </message>
    <message>
        <source>has no base model</source>
        <translation>ベースモデルがありません</translation>
    </message>
    <message>
        <source>Deforms a key with the falloff brush, seen from the key&apos;s camera.</source>
        <translation>キーのカメラから見て、減衰付きブラシでキーを変形します。</translation>
    </message>
    <message>
        <source>Name of the key to deform.</source>
        <translation>変形するキーの名前。</translation>
    </message>
    <message>
        <source>Index of the picked vertex.</source>
        <translation>選択する頂点のインデックス。</translation>
    </message>
    <message>
        <source>Selection radius in world units.</source>
        <translation>選択半径（ワールド単位）。</translation>
    </message>
    <message>
        <source>Move along the camera&apos;s right and up vectors, in world units.</source>
        <translation>カメラの右方向と上方向に沿った移動量（ワールド単位）。</translation>
    </message>
    <message>
        <source>Move along the viewing direction (away from the camera), in world units.</source>
        <translation>視線方向（カメラから遠ざかる向き）に沿った移動量（ワールド単位）。</translation>
    </message>
    <message>
        <source>Print what moved as JSON.</source>
        <translation>移動した内容を JSON 形式で出力します。</translation>
    </message>
    <message>
        <source>--radius must be positive</source>
        <translation>--radius には正の値を指定してください</translation>
    </message>
    <message>
        <source>Frame (default 0).</source>
        <translation>フレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>Write the blended mesh (OBJ or PLY, base vertex order).</source>
        <translation>ブレンドしたメッシュを書き出します（OBJ または PLY、ベースモデルの頂点順序）。</translation>
    </message>
    <message>
        <source>Changes project settings.</source>
        <translation>プロジェクトの設定を変更します。</translation>
    </message>
    <message>
        <source>Unspecified-region mode.</source>
        <translation>未指定領域のモード。</translation>
    </message>
    <message>
        <source>Key light: a point position or a direction towards the light.</source>
        <translation>キーライト: 点光源の位置、またはライトに向かう方向。</translation>
    </message>
    <message>
        <source>Shading style.</source>
        <translation>シェーディングスタイル。</translation>
    </message>
    <message>
        <source>--unspecified takes dummy, cosine or cosine2, not “%1”</source>
        <translation>--unspecified には dummy、cosine、cosine2 のいずれかを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>usage:</source>
        <translation>使い方:</translation>
    </message>
    <message>
        <source>--%1 needs three numbers X,Y,Z, not “%2”</source>
        <translation>--%1 には X,Y,Z の 3 つの数値が必要です（「%2」ではありません）</translation>
    </message>
    <message>
        <source>--%1 needs two numbers A,B, not “%2”</source>
        <translation>--%1 には A,B の 2 つの数値が必要です（「%2」ではありません）</translation>
    </message>
    <message>
        <source>--size takes WIDTHxHEIGHT between 1 and 16384, not “%1”</source>
        <translation>--size には 1～16384 の範囲で WIDTHxHEIGHT を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>Renders the project&apos;s look without a display (CPU renderer).</source>
        <translation>ディスプレイを使わずにプロジェクトのルックをレンダリングします（CPU レンダラー）。</translation>
    </message>
    <message>
        <source>Frame to render (default 0).</source>
        <translation>レンダリングするフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>Image size (default 1280x720).</source>
        <translation>画像サイズ（既定値 1280x720）。</translation>
    </message>
    <message>
        <source>Shading style of this picture (default: the project&apos;s).</source>
        <translation>この画像のシェーディングスタイル（既定ではプロジェクトのもの）。</translation>
    </message>
    <message>
        <source>Key light of this picture (default: the project&apos;s).</source>
        <translation>この画像のキーライト（既定ではプロジェクトのもの）。</translation>
    </message>
    <message>
        <source>Stereo output.</source>
        <translation>ステレオ出力。</translation>
    </message>
    <message>
        <source>Write one render pass.</source>
        <translation>レンダーパスを 1 つだけ書き出します。</translation>
    </message>
    <message>
        <source>give either --frame or --frames</source>
        <translation>--frame と --frames はどちらか一方だけを指定してください</translation>
    </message>
    <message>
        <source>--stereo takes off, anaglyph, dubois, halfcolor, sbs or tb, not “%1”</source>
        <translation>--stereo には off、anaglyph、dubois、halfcolor、sbs、tb のいずれかを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--pass takes one of %1, not “%2”</source>
        <translation>--pass には %1 のいずれかを指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>a stereo render writes the beauty pass only</source>
        <translation>ステレオレンダリングで書き出せるのは beauty パスのみです</translation>
    </message>
    <message>
        <source>--combine takes union:OTHER or subtract:OTHER, not “%1”</source>
        <translation>--combine には union:OTHER または subtract:OTHER を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>Adds, keys and lists stylized highlight layers.</source>
        <translation>スタイライズドハイライトのレイヤーを追加し、キーフレームを設定し、一覧を表示します。</translation>
    </message>
    <message>
        <source>List the highlight layers.</source>
        <translation>ハイライトレイヤーの一覧を表示します。</translation>
    </message>
    <message>
        <source>Add a layer, or with --frame key an existing one.</source>
        <translation>レイヤーを追加します。--frame を指定した場合は既存のレイヤーにキーフレームを設定します。</translation>
    </message>
    <message>
        <source>Face set the highlight may appear on (all: every face).</source>
        <translation>ハイライトを表示できるフェースセット（all: すべての面）。</translation>
    </message>
    <message>
        <source>Size of the area, in (0, 1] (default 0.05).</source>
        <translation>ハイライト領域のサイズ。(0, 1] の範囲で指定（既定値 0.05）。</translation>
    </message>
    <message>
        <source>Direction of the u axis on models without UVs (default 0,1,0).</source>
        <translation>UV のないモデルでの u 軸の方向（既定値 0,1,0）。</translation>
    </message>
    <message>
        <source>Linear RGB colour in [0, 1] (default 1,1,1).</source>
        <translation>リニア RGB の色。各成分は [0, 1] の範囲で指定（既定値 1,1,1）。</translation>
    </message>
    <message>
        <source>Off-specular cut: no highlight where N.L &lt;= C (default -1: off).</source>
        <translation>オフスペキュラーカット: N.L &lt;= C の部分にはハイライトを表示しません（既定値 -1: オフ）。</translation>
    </message>
    <message>
        <source>Operation, in order (repeatable): translate:A,B rotate:DEG scale:DELTA split:G1,G2 square:SIGMA,N.</source>
        <translation>操作（指定した順に適用、複数指定可）: translate:A,B rotate:DEG scale:DELTA split:G1,G2 square:SIGMA,N。</translation>
    </message>
    <message>
        <source>Unite with or subtract another layer&apos;s area (repeatable).</source>
        <translation>別のレイヤーの領域との和または差をとります（複数指定可）。</translation>
    </message>
    <message>
        <source>Draw the layer (on) or use it only in combinations (off).</source>
        <translation>レイヤーを描画するかどうか（on: 描画する、off: 組み合わせにのみ使用する）。</translation>
    </message>
    <message>
        <source>Frame of the keyframe (default 0).</source>
        <translation>キーフレームのフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>%1	patch %2	%3 keyframes
</source>
        <translation>%1	パッチ %2	キーフレーム %3 個
</translation>
    </message>
    <message>
        <source>--add needs a layer name</source>
        <translation>--add にはレイヤー名を指定してください</translation>
    </message>
    <message>
        <source>--epsilon must lie in (0, 1], not “%1”</source>
        <translation>--epsilon には (0, 1] の範囲の値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--cut must lie in [-1, 1], not “%1”</source>
        <translation>--cut には [-1, 1] の範囲の値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--color components must lie in [0, 1], not “%1”</source>
        <translation>--color の各成分には [0, 1] の範囲の値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--combine needs another layer than “%1” itself</source>
        <translation>--combine には「%1」自身以外のレイヤーを指定してください</translation>
    </message>
    <message>
        <source>already has a highlight layer named “%1”; give --frame F to set a keyframe of it</source>
        <translation>「%1」という名前のハイライトレイヤーがすでにあります。このレイヤーにキーフレームを設定するには --frame F を指定してください</translation>
    </message>
    <message>
        <source>has no face set named “%1”</source>
        <translation>「%1」という名前のフェースセットがありません</translation>
    </message>
    <message>
        <source>has no highlight layer named “%1”</source>
        <translation>「%1」という名前のハイライトレイヤーがありません</translation>
    </message>
    <message>
        <source>warning: %1: the keyframes %2 and %3 of “%4” have different operations; the earlier one holds between them</source>
        <translation>警告: %1: 「%4」のキーフレーム %2 と %3 で操作が異なります。この 2 つの間では前のキーフレームが保持されます</translation>
    </message>
    <message>
        <source>--%1 needs four numbers X,Y,Z,R, not “%2”</source>
        <translation>--%1 には 4 つの数 X,Y,Z,R が必要です（「%2」ではなく）</translation>
    </message>
    <message>
        <source>Rounds of normal smoothing over the patch for this layer (default 0: the surface&apos;s normals).</source>
        <translation>このレイヤーのパッチ上で法線を平滑化する回数（既定 0: 面の法線のまま）。</translation>
    </message>
    <message>
        <source>--smooth must lie in [0, %1], not “%2”</source>
        <translation>--smooth は [0, %1] の範囲で指定してください（「%2」ではなく）</translation>
    </message>
    <message>
        <source>--faces takes indices and ranges like 0-99,120, not “%1”</source>
        <translation>--faces には 0-99,120 のような番号と範囲を指定します（「%1」ではなく）</translation>
    </message>
    <message>
        <source>has %1 faces; face %2 does not exist</source>
        <translation>の面は %1 個です。面 %2 はありません</translation>
    </message>
    <message>
        <source>List the patches.</source>
        <translation>パッチを一覧表示します。</translation>
    </message>
    <message>
        <source>Add the selected faces to a patch (made when missing).</source>
        <translation>選んだ面をパッチに加えます（なければ作成）。</translation>
    </message>
    <message>
        <source>Take the selected faces out of a patch.</source>
        <translation>選んだ面をパッチから外します。</translation>
    </message>
    <message>
        <source>Delete a patch; its highlight layers go back to all faces.</source>
        <translation>パッチを削除します。そのハイライトレイヤーは全面に戻ります。</translation>
    </message>
    <message>
        <source>Select the faces with a corner inside a sphere (repeatable).</source>
        <translation>頂点のひとつが球の内側にある面を選びます（繰り返し可）。</translation>
    </message>
    <message>
        <source>Select faces by index (repeatable).</source>
        <translation>番号で面を選びます（繰り返し可）。</translation>
    </message>
    <message>
        <source>Select a material&apos;s faces (repeatable).</source>
        <translation>マテリアルの面を選びます（繰り返し可）。</translation>
    </message>
    <message>
        <source>--sphere needs a positive radius, not “%1”</source>
        <translation>--sphere には正の半径が必要です（「%1」ではなく）</translation>
    </message>
    <message>
        <source>%1	%2 faces
</source>
        <translation>%1	%2 面
</translation>
    </message>
    <message>
        <source>has no patch named “%1”</source>
        <translation>に「%1」という名前のパッチはありません</translation>
    </message>
    <message>
        <source>has no material named “%1”</source>
        <translation>に「%1」という名前のマテリアルはありません</translation>
    </message>
    <message>
        <source>a patch needs a name</source>
        <translation>パッチには名前が必要です</translation>
    </message>
    <message>
        <source>Remove a layer and its use in other layers&apos; combinations.</source>
        <translation>レイヤーと、他のレイヤーの組み合わせでのその使用を削除します。</translation>
    </message>
    <message>
        <source>Rename a layer (with --to).</source>
        <translation>レイヤーの名前を変更します（--to と一緒に）。</translation>
    </message>
    <message>
        <source>The new name of --rename.</source>
        <translation>--rename の新しい名前。</translation>
    </message>
    <message>
        <source>--to needs a new name no other layer has, not “%1”</source>
        <translation>--to には他のレイヤーにない新しい名前が必要です（「%1」ではなく）</translation>
    </message>
    <message>
        <source>The render camera: looking at the model&apos;s centroid from this direction, framed; none removes it.</source>
        <translation>レンダーカメラ: この方向からモデルの重心を見て、全体が収まる位置に置きます。none で削除します。</translation>
    </message>
    <message>
        <source>has no base model to frame a render camera on</source>
        <translation>にレンダーカメラを合わせるベースモデルがありません</translation>
    </message>
    <message>
        <source>Interpolation of key deformations over frames: natural (cubic spline, held outside the keyed frames) or periodic (a looping cycle).</source>
        <translation>キー変形のフレーム間の補間: natural（3 次スプライン、キーのあるフレームの外側では保持）または periodic（ループするサイクル）。</translation>
    </message>
    <message>
        <source>--time takes natural or periodic, not “%1”</source>
        <translation>--time には natural か periodic を指定してください（「%1」ではなく）</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>このヘルプを表示します。</translation>
    </message>
    <message>
        <source>Arguments:</source>
        <translation>引数:</translation>
    </message>
    <message>
        <source>Options:</source>
        <translation>オプション:</translation>
    </message>
    <message>
        <source>Without a sub-command celform opens the editor (it needs a display). The sub-commands run without one:</source>
        <translation>サブコマンドを指定しない場合、celform はエディターを開きます（ディスプレイが必要です）。サブコマンドはディスプレイなしで実行できます:</translation>
    </message>
    <message>
        <source>celform SUB-COMMAND --help describes each option.</source>
        <translation>各オプションの説明は celform SUB-COMMAND --help で表示されます。</translation>
    </message>
    <message>
        <source>Exit codes: 0 success, 2 usage error, 3 bad input.</source>
        <translation>終了コード: 0 成功、2 使い方の誤り、3 不正な入力。</translation>
    </message>
    <message>
        <source>missing arguments</source>
        <translation>引数が足りません</translation>
    </message>
    <message>
        <source>unexpected argument “%1”</source>
        <translation>予期しない引数「%1」です</translation>
    </message>
    <message>
        <source>celform: unknown sub-command “%1”</source>
        <translation>celform: 不明なサブコマンド「%1」です</translation>
    </message>
    <message>
        <source>(celform %1 --help describes each option)</source>
        <translation>（各オプションの説明は celform %1 --help で表示されます）</translation>
    </message>
    <message>
        <source>--op takes translate:A,B, rotate:DEG, scale:DELTA, split:G1,G2 or square:SIGMA,N, not “%1”</source>
        <translation>--op には translate:A,B、rotate:DEG、scale:DELTA、split:G1,G2、square:SIGMA,N のいずれかを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--op “%1”: %2</source>
        <translation>--op「%1」: %2</translation>
    </message>
    <message>
        <source>give one of --list, --add NAME with its options, --remove NAME or --rename NAME --to NEW</source>
        <translation>--list、オプション付きの --add NAME、--remove NAME、--rename NAME --to NEW のいずれかを指定してください</translation>
    </message>
    <message>
        <source>unknown key action “%1”</source>
        <translation>不明な key の操作「%1」です</translation>
    </message>
    <message>
        <source>--name and exactly one of --mesh or --from-base are required</source>
        <translation>--name と、--mesh または --from-base のどちらか一方の指定が必要です</translation>
    </message>
    <message>
        <source>--key, --vertex, --radius and exactly one of --drag or --push are required</source>
        <translation>--key、--vertex、--radius と、--drag または --push のどちらか一方の指定が必要です</translation>
    </message>
    <message>
        <source>has no key named “%1”</source>
        <translation>「%1」という名前のキーがありません</translation>
    </message>
    <message>
        <source>(celform --help lists the sub-commands)</source>
        <translation>（サブコマンドの一覧は celform --help で表示されます）</translation>
    </message>
    <message>
        <source>unknown sub-command “%1”; the sub-commands are %2 (celform --help)</source>
        <translation>不明なサブコマンド「%1」です。サブコマンドは %2 です（celform --help）</translation>
    </message>
    <message>
        <source>%1: the file does not exist</source>
        <translation>%1: ファイルが存在しません</translation>
    </message>
    <message>
        <source>the editor needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is set (run it under xvfb-run, or set QT_QPA_PLATFORM); the sub-commands need none (celform --help)</source>
        <translation>エディターにはディスプレイが必要ですが、DISPLAY も WAYLAND_DISPLAY も設定されていません（xvfb-run の下で実行するか、QT_QPA_PLATFORM を設定してください）。サブコマンドはディスプレイなしで実行できます（celform --help）</translation>
    </message>
    <message>
        <source>celform: the editor module %1 is missing (looked in %2)</source>
        <translation>celform: エディターモジュール %1 が見つかりません（検索場所: %2）</translation>
    </message>
    <message>
        <source>celform: %1: the editor module cannot be loaded: %2</source>
        <translation>celform: %1: エディターモジュールを読み込めません: %2</translation>
    </message>
    <message>
        <source>nothing to set</source>
        <translation>設定する項目が指定されていません</translation>
    </message>
    <message>
        <source>%1: “%2” is too large</source>
        <translation>%1: 「%2」は大きすぎます</translation>
    </message>
    <message>
        <source>%1 takes a frame number between -%2 and %2, not “%3”</source>
        <translation>%1 には -%2～%2 の範囲のフレーム番号を指定してください（「%3」は無効です）</translation>
    </message>
    <message>
        <source>%1 takes frame numbers between -%2 and %2, not “%3”</source>
        <translation>%1 のフレーム番号はどちらも -%2～%2 の範囲で指定してください（「%3」は無効です）</translation>
    </message>
    <message>
        <source>%1 takes at most %2 frames at a time, not “%3”</source>
        <translation>%1 で一度に指定できるのは %2 フレームまでです（「%3」は無効です）</translation>
    </message>
    <message>
        <source>%1 takes on or off, not “%2”</source>
        <translation>%1 には on または off を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>%1 needs a direction: not zero, and short enough that its length is a number, not “%2”</source>
        <translation>%1 には方向を指定してください。ゼロではなく、長さが有限の数値に収まる程度に短いベクトルが必要です（「%2」は無効です）</translation>
    </message>
    <message>
        <source>--light takes point:X,Y,Z or directional:X,Y,Z, not “%1”</source>
        <translation>--light には point:X,Y,Z または directional:X,Y,Z を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--style takes toon, gooch, comic or lambert, not “%1”</source>
        <translation>--style には toon、gooch、comic、lambert のいずれかを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>give either --view or --eye, --target and --up</source>
        <translation>--view か、--eye・--target・--up の組み合わせのどちらか一方だけを指定してください</translation>
    </message>
    <message>
        <source>--eye, --target and --up go together</source>
        <translation>--eye、--target、--up は 3 つともまとめて指定してください</translation>
    </message>
    <message>
        <source>give either --view or all of --eye, --target and --up</source>
        <translation>--view を指定するか、--eye、--target、--up をすべて指定してください</translation>
    </message>
    <message>
        <source>--eye, --target and --up do not make a camera (eye equals target, or up is parallel to the view)</source>
        <translation>--eye、--target、--up ではカメラを構成できません（eye と target が同じか、up が視線方向と平行です）</translation>
    </message>
    <message>
        <source>--out is required</source>
        <translation>--out の指定が必要です</translation>
    </message>
    <message>
        <source>--name needs a name, not “%1”</source>
        <translation>--name には名前が必要です（“%1” ではなく）</translation>
    </message>
    <message>
        <source>warning: %1: a key named “%2” exists; the new key is named “%3”</source>
        <translation>警告: %1: “%2” という名前のキーがすでにあります。新しいキーの名前は “%3” です</translation>
    </message>
    <message>
        <source>--falloff must be paper, smooth or sphere, not “%1”</source>
        <translation>--falloff は paper、smooth、sphere のいずれかです（“%1” ではなく）</translation>
    </message>
    <message>
        <source>--strength must be in (0, 1]</source>
        <translation>--strength は (0, 1] の範囲で指定してください</translation>
    </message>
    <message>
        <source>Falloff curve: paper ((1 - d/r)^2, the default), smooth or sphere.</source>
        <translation>減衰カーブ: paper（(1 - d/r)^2、既定）、smooth、sphere。</translation>
    </message>
    <message>
        <source>Strength in (0, 1], 1 by default.</source>
        <translation>強さ (0, 1]、既定は 1。</translation>
    </message>
    <message>
        <source>%1 takes at most %2 pixels (8192x8192: the renderer holds %3 bytes a pixel), not “%4”</source>
        <translation>%1 は最大 %2 ピクセルです（8192x8192: レンダラーは 1 ピクセルに %3 バイトを使います）。“%4” は指定できません</translation>
    </message>
    <message>
        <source>%1 %2 needs about %3 GB of memory to render, and %4 GB are available</source>
        <translation>%1 %2 のレンダリングには約 %3 GB のメモリが必要ですが、使えるのは %4 GB です</translation>
    </message>
    <message>
        <source>--out “%1” is one of the files being read; give a new .celform file</source>
        <translation>--out “%1” は読み込むファイルの一つです。新しい .celform ファイルを指定してください</translation>
    </message>
    <message>
        <source>--out must end in .celform, not “%1”</source>
        <translation>--out は .celform で終わる必要があります（“%1” ではなく）</translation>
    </message>
    <message>
        <source>--window takes LO,HI with 0 &lt;= LO &lt;= HI &lt;= 1, or lenient, medium or strict, not “%1”</source>
        <translation>--window には 0 &lt;= LO &lt;= HI &lt;= 1 の LO,HI、または lenient、medium、strict を指定します（“%1” ではありません）</translation>
    </message>
    <message>
        <source>--out must end in .exr, not “%1”</source>
        <translation>--out は .exr で終わる必要があります（“%1” ではありません）</translation>
    </message>
    <message>
        <source>segment	pixels	ratio	in window</source>
        <translation>セグメント	ピクセル	比率	範囲内</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <source>no</source>
        <translation>いいえ</translation>
    </message>
    <message numerus="yes">
        <source>%n segment(s), %1 inside the window %2-%3</source>
        <translation>
            <numerusform>%n 個のセグメント、範囲 %2-%3 の内側に %1 個</numerusform>
        </translation>
    </message>
    <message>
        <source>depth error: MSE %1, RMSE %2 (model units; %3 of %4 model pixels are features)</source>
        <translation>奥行き誤差: MSE %1、RMSE %2（モデル単位。モデルの %4 ピクセル中 %3 ピクセルが特徴ピクセル）</translation>
    </message>
    <message>
        <source>time: %1 ms (curvature %2 ms)</source>
        <translation>時間: %1 ms（曲率 %2 ms）</translation>
    </message>
    <message>
        <source>--out must end in .ply, not “%1”</source>
        <translation>--out は .ply で終わる必要があります（“%1” ではありません）</translation>
    </message>
    <message>
        <source>--out would overwrite the project</source>
        <translation>--out がプロジェクトを上書きしてしまいます</translation>
    </message>
    <message>
        <source>Frame to analyse (default 0).</source>
        <translation>解析するフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>Picture size (default 1280x720).</source>
        <translation>画像サイズ（既定値 1280x720）。</translation>
    </message>
    <message>
        <source>Bright/dark ratio window a segment should be in: LO,HI, lenient (0.2-0.8), medium (0.35-0.65, the default) or strict (0.5).</source>
        <translation>セグメントの明暗比が収まるべき範囲: LO,HI、lenient（0.2-0.8）、medium（0.35-0.65、既定）、strict（0.5）。</translation>
    </message>
    <message>
        <source>Neighbouring pixels whose depths differ by this fraction of the model&apos;s bounding-box diagonal or more are in different segments (default 0.02).</source>
        <translation>奥行きの差がモデルのバウンディングボックス対角線のこの割合以上ある隣接ピクセルは別のセグメントになります（既定値 0.02）。</translation>
    </message>
    <message>
        <source>Segments smaller than this are dropped as noise (default 64).</source>
        <translation>これより小さいセグメントはノイズとして除きます（既定値 64）。</translation>
    </message>
    <message>
        <source>Stereo depth analysis of the picture: segments with their bright/dark ratios, and the depth error.</source>
        <translation>画像の立体視奥行き解析: セグメントとその明暗比、および奥行き誤差。</translation>
    </message>
    <message>
        <source>Writes the per-vertex principal curvatures k1, k2 and the Gaussian curvature K as PLY properties.</source>
        <translation>頂点ごとの主曲率 k1、k2 とガウス曲率 K を PLY のプロパティとして書き出します。</translation>
    </message>
    <message>
        <source>Frame of the shape (default 0).</source>
        <translation>形状のフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>The view-dependent shape seen from this direction (default: the base model).</source>
        <translation>この方向から見たビュー依存形状（既定: ベースモデル）。</translation>
    </message>
    <message>
        <source>The PLY file to write.</source>
        <translation>書き出す PLY ファイル。</translation>
    </message>
    <message>
        <source>--method must be gradient, annealing or random, not “%1”</source>
        <translation>--method には gradient、annealing、random のいずれかを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--weight must be constant or area, not “%1”</source>
        <translation>--weight には constant または area を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--iterations takes a whole number from 1 to 100000, not “%1”</source>
        <translation>--iterations には 1～100000 の整数を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--seed takes a whole number of at least 0, not “%1”</source>
        <translation>--seed には 0 以上の整数を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>point</source>
        <translation>点光源</translation>
    </message>
    <message>
        <source>directional</source>
        <translation>平行光源</translation>
    </message>
    <message>
        <source>light: %1 -&gt; %2</source>
        <translation>ライト: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>segments inside the window: %1 -&gt; %2 of %3</source>
        <translation>範囲内のセグメント: %1 -&gt; %2（%3 個中）</translation>
    </message>
    <message>
        <source>depth error MSE: %1 -&gt; %2</source>
        <translation>奥行き誤差 MSE: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>time: %1 ms (iterations %2 ms)</source>
        <translation>時間: %1 ms（反復 %2 ms）</translation>
    </message>
    <message>
        <source>not saved (--dry-run)</source>
        <translation>保存していません（--dry-run）</translation>
    </message>
    <message>
        <source>the light stays where it is</source>
        <translation>ライトは移動しません</translation>
    </message>
    <message>
        <source>Size of the analysed picture (default 1280x720).</source>
        <translation>解析する画像のサイズ（既定値 1280x720）。</translation>
    </message>
    <message>
        <source>How much each segment counts: all alike (constant, the default: small dents count as much as the body) or by its size (area).</source>
        <translation>各セグメントの重み: すべて同等（constant、既定: 小さなくぼみも本体と同じだけ重視）または大きさに応じる（area）。</translation>
    </message>
    <message>
        <source>gradient (the default: moves the light from where it is along the shading&apos;s derivative), annealing (shrinking random steps) or random (independent random lights, the best kept).</source>
        <translation>gradient（既定: シェーディングの微分に沿って現在の位置からライトを動かす）、annealing（幅を狭めていくランダムな移動）、random（独立したランダムなライトを試し、最良のものを残す）。</translation>
    </message>
    <message>
        <source>Iterations (default 64).</source>
        <translation>反復回数（既定値 64）。</translation>
    </message>
    <message>
        <source>Seed of the annealing and random methods (default 1).</source>
        <translation>annealing と random の手法で使う乱数シード（既定値 1）。</translation>
    </message>
    <message>
        <source>Report the light found without saving it.</source>
        <translation>見つかったライトを保存せずに表示します。</translation>
    </message>
    <message>
        <source>Moves the key light so that every segment&apos;s bright/dark ratio gets into the window, and saves the project.</source>
        <translation>すべてのセグメントの明暗比が範囲内に収まるようにキーライトを動かし、プロジェクトを保存します。</translation>
    </message>
    <message>
        <source>--ridge-threshold takes a number &gt;= 0, not “%1”</source>
        <translation>--ridge-threshold には 0 以上の数値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>Draw the lines (on) or not (off), or only these kinds: silhouette, crease, border, material, ridge (apparent ridges), comma-separated.</source>
        <translation>線を描くか（on）描かないか（off）、または描く線の種類だけをカンマ区切りで指定: silhouette、crease、border、material、ridge（見かけの稜線）。</translation>
    </message>
    <message>
        <source>exactly one of --auto, --clear or --smooth is required</source>
        <translation>--auto、--clear、--smooth のいずれか 1 つだけを指定してください</translation>
    </message>
    <message>
        <source>camera, picture and solve options go with --auto only</source>
        <translation>カメラ、画像、求解のオプションは --auto と一緒にしか使えません</translation>
    </message>
    <message>
        <source>--aggressiveness must be in [0, 1]</source>
        <translation>--aggressiveness は [0, 1] の範囲で指定してください</translation>
    </message>
    <message>
        <source>--percentile must be in [0, 1]</source>
        <translation>--percentile は [0, 1] の範囲で指定してください</translation>
    </message>
    <message>
        <source>--bleed must be a whole number from 0 to %1</source>
        <translation>--bleed には 0～%1 の整数を指定してください</translation>
    </message>
    <message>
        <source>--smooth must be a whole number from 1 to %1</source>
        <translation>--smooth には 1～%1 の整数を指定してください</translation>
    </message>
    <message>
        <source>%1 segments, %2 inside the ratio window before, %3 after; depth error MSE %4 before, %5 after (%6 ms)</source>
        <translation>セグメント %1 個、比率の範囲内: 適用前 %2 個、適用後 %3 個。奥行き誤差 MSE: 適用前 %4、適用後 %5（%6 ms）</translation>
    </message>
    <message>
        <source>Remove the target&apos;s offsets.</source>
        <translation>対象のオフセットを削除します。</translation>
    </message>
    <message>
        <source>N rounds of smoothing over the mesh&apos;s vertex neighbours.</source>
        <translation>メッシュの隣接頂点間で N 回平滑化します。</translation>
    </message>
    <message>
        <source>Frame analysed, and the key layer&apos;s frame (default 0; --clear on a key without it clears every frame).</source>
        <translation>解析するフレーム、およびキーのレイヤーのフレーム（既定値 0。キーに対してこのオプションなしで --clear を使うと、すべてのフレームを消去します）。</translation>
    </message>
    <message>
        <source>Analysed picture size (default 1280x720).</source>
        <translation>解析する画像のサイズ（既定値 1280x720）。</translation>
    </message>
    <message>
        <source>How far towards the solved offsets, in [0, 1] (default 1).</source>
        <translation>求めたオフセットにどこまで近づけるか、[0, 1]（既定値 1）。</translation>
    </message>
    <message>
        <source>Fraction of each segment left dark, in [0, 1] (default 0.5).</source>
        <translation>各セグメントで暗部として残す割合、[0, 1]（既定値 0.5）。</translation>
    </message>
    <message>
        <source>Rounds the offsets bleed to neighbouring vertices (default 2).</source>
        <translation>オフセットを隣接頂点ににじませる回数（既定値 2）。</translation>
    </message>
    <message>
        <source>Edit this key&apos;s layer instead of the base layer.</source>
        <translation>ベースレイヤーではなく、このキーのレイヤーを編集します。</translation>
    </message>
    <message>
        <source>Shading offsets (paper 3, section 4.3): automatic per segment, cleared or smoothed; saved in the project.</source>
        <translation>シェーディングオフセット（論文 3、4.3 節）: セグメントごとの自動設定、消去、平滑化を行い、プロジェクトに保存します。</translation>
    </message>
    <message>
        <source>exactly one of --turntable, --key, --clear or --list is required</source>
        <translation>--turntable、--key、--clear、--list のいずれか 1 つだけを指定してください</translation>
    </message>
    <message>
        <source>--axis, --elevation, --start and --start-angle go with --turntable only</source>
        <translation>--axis、--elevation、--start、--start-angle は --turntable と一緒にしか使えません</translation>
    </message>
    <message>
        <source>camera options go with --key only</source>
        <translation>カメラのオプションは --key と一緒にしか使えません</translation>
    </message>
    <message>
        <source>--json goes with --list</source>
        <translation>--json は --list と一緒に指定してください</translation>
    </message>
    <message>
        <source>--turntable takes 2 to %1 frames</source>
        <translation>--turntable には 2～%1 のフレーム数を指定してください</translation>
    </message>
    <message>
        <source>No camera path: renders use the render camera.</source>
        <translation>カメラパスがありません。レンダーにはレンダーカメラを使います。</translation>
    </message>
    <message>
        <source>Replace the path by a turntable: one revolution in FRAMES frames (also sets the frame range).</source>
        <translation>パスをターンテーブルで置き換えます: FRAMES フレームで 1 周します（フレーム範囲も設定します）。</translation>
    </message>
    <message>
        <source>Turntable axis (default 0,1,0).</source>
        <translation>ターンテーブルの軸（既定値 0,1,0）。</translation>
    </message>
    <message>
        <source>Turntable camera height above the orbit plane (default 15).</source>
        <translation>軌道面からのターンテーブルカメラの高さ（既定値 15）。</translation>
    </message>
    <message>
        <source>Turntable&apos;s first frame (default 0).</source>
        <translation>ターンテーブルの最初のフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>Turntable&apos;s angle at its first frame.</source>
        <translation>最初のフレームでのターンテーブルの角度。</translation>
    </message>
    <message>
        <source>Key the camera given by the camera options at frame F.</source>
        <translation>カメラのオプションで指定したカメラをフレーム F にキーフレームとして設定します。</translation>
    </message>
    <message>
        <source>Remove the camera path.</source>
        <translation>カメラパスを削除します。</translation>
    </message>
    <message>
        <source>Print the camera keys.</source>
        <translation>カメラのキーフレームを表示します。</translation>
    </message>
    <message>
        <source>Edits the shot&apos;s camera path: a turntable, keyed cameras, clearing; renders and eval without camera options look through it.</source>
        <translation>ショットのカメラパスを編集します: ターンテーブル、カメラのキーフレーム、消去。カメラのオプションを指定しない render と eval はこのパスから見ます。</translation>
    </message>
    <message>
        <source>--format and --out are required</source>
        <translation>--format と --out の指定が必要です</translation>
    </message>
    <message>
        <source>--out needs a file name</source>
        <translation>--out にはファイル名が必要です</translation>
    </message>
    <message>
        <source>--out must end in .%1 for --format %2, not “%3”</source>
        <translation>--format %2 では --out は .%1 で終わる必要があります（「%3」は無効です）</translation>
    </message>
    <message>
        <source>--frames takes A-B for an export, without a step: “%1”</source>
        <translation>エクスポートでは --frames にステップなしの A-B を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>export: frame %1 of %2</source>
        <translation>エクスポート: フレーム %1 / %2</translation>
    </message>
    <message>
        <source>Frames to export, A-B inclusive (default the project&apos;s).</source>
        <translation>エクスポートするフレーム、A-B（両端を含む。既定値はプロジェクトの範囲）。</translation>
    </message>
    <message>
        <source>The file; for obj-seq a pattern where a run of # is the frame number (else _FFFF goes before .obj).</source>
        <translation>ファイル。obj-seq では連続した # がフレーム番号になるパターン（# がなければ .obj の前に _FFFF が付きます）。</translation>
    </message>
    <message>
        <source>Print the camera, keys and weights as JSON.</source>
        <translation>カメラ、キー、ウェイトを JSON 形式で出力します。</translation>
    </message>
    <message>
        <source>Evaluates the view-dependent shape at a frame: for a view direction or a camera, else through the camera path (or the render camera) at that frame.</source>
        <translation>あるフレームでの視点依存の形状を評価します: 視線方向かカメラを指定した場合はそれに対して、指定しない場合はそのフレームのカメラパス（またはレンダーカメラ）から見て評価します。</translation>
    </message>
    <message>
        <source>--threads takes a whole number of at least 1, not “%1”</source>
        <translation>--threads には 1 以上の整数を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>warning: rendering %1 frames at a time, not %2: each needs about %3 GB of memory at %4, and %5 GB are available</source>
        <translation>警告: 一度にレンダーするのは %2 フレームではなく %1 フレームにします。%4 では 1 フレームに約 %3 GB のメモリが必要ですが、使えるのは %5 GB です</translation>
    </message>
    <message>
        <source>frame %1 (%2/%3) -&gt; %4</source>
        <translation>フレーム %1 (%2/%3) -&gt; %4</translation>
    </message>
    <message>
        <source>frame %1 (%2/%3) skipped: %4 exists</source>
        <translation>フレーム %1 (%2/%3) をスキップしました: %4 はすでにあります</translation>
    </message>
    <message>
        <source>frame %1: %2</source>
        <translation>フレーム %1: %2</translation>
    </message>
    <message>
        <source>Frames to render, A-B inclusive, every STEP-th from A (default 1); each to a file of its own (a # in --out, or _####, is the frame number).</source>
        <translation>レンダーするフレーム、A-B（両端を含む）、A から STEP フレームごと（既定値 1）。各フレームを別々のファイルに書き出します（--out 内の #、または _#### がフレーム番号になります）。</translation>
    </message>
    <message>
        <source>Frames rendered at once (default: one per processor; fewer when memory is short). The files are the same for any N.</source>
        <translation>一度にレンダーするフレーム数（既定: プロセッサーごとに 1。メモリが足りないときは減らします）。N によらず同じファイルが得られます。</translation>
    </message>
    <message>
        <source>Leave frames whose file exists as they are (to resume an interrupted render).</source>
        <translation>ファイルがすでにあるフレームはそのままにします（中断したレンダーの再開用）。</translation>
    </message>
    <message>
        <source>Print the frames written and skipped as JSON.</source>
        <translation>書き出したフレームとスキップしたフレームを JSON 形式で出力します。</translation>
    </message>
    <message>
        <source>%1 takes A-B or A-B:STEP with A &lt;= B and STEP &gt;= 1, not “%2”</source>
        <translation>%1 には A &lt;= B、STEP &gt;= 1 の A-B または A-B:STEP を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>--fps must lie in (0, %1]</source>
        <translation>--fps は (0, %1] の範囲で指定してください</translation>
    </message>
    <message>
        <source>Frames: %1-%2 at %3 fps</source>
        <translation>フレーム: %1-%2（%3 fps）</translation>
    </message>
    <message>
        <source>Animated base: %1 frames from frame %2</source>
        <translation>アニメーションするベースモデル: フレーム %2 から %1 フレーム</translation>
    </message>
    <message>
        <source>Camera path: %1 keys</source>
        <translation>カメラパス: キーフレーム %1 個</translation>
    </message>
    <message>
        <source>Creates a project from a mesh file, or from an animated base (a glTF/GLB with skins or morph targets, or an OBJ/PLY sequence such as walk_####.obj).</source>
        <translation>メッシュファイル、またはアニメーションするベースモデル（スキンやモーフターゲットを持つ glTF/GLB、または walk_####.obj のような OBJ/PLY の連番）からプロジェクトを作成します。</translation>
    </message>
    <message>
        <source>Frames per second an animated base is sampled at (default 24); frame F is time F / fps.</source>
        <translation>アニメーションするベースモデルをサンプリングするフレームレート（既定値 24）。フレーム F は時刻 F / fps です。</translation>
    </message>
    <message>
        <source>MESH is one numbered file of a sequence (walk_0001.obj): read it with its numbered siblings as frames.</source>
        <translation>MESH は連番ファイルの 1 つ（walk_0001.obj）です。同じ連番のほかのファイルとともにフレームとして読み込みます。</translation>
    </message>
    <message>
        <source>--drawing and --out are required</source>
        <translation>--drawing と --out は必須です</translation>
    </message>
    <message>
        <source>--out must name an .svg or .png file, not “%1”</source>
        <translation>--out には .svg または .png ファイルを指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--key is required</source>
        <translation>--key は必須です</translation>
    </message>
    <message>
        <source>give --camera, --shape or both</source>
        <translation>--camera、--shape、またはその両方を指定してください</translation>
    </message>
    <message>
        <source>--iterations takes a whole number from 1 to 100, not “%1”</source>
        <translation>--iterations には 1～100 の整数を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--strength takes a number from 0 to 1, not “%1”</source>
        <translation>--strength には 0～1 の数値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>fitting the camera: %1 of %2</source>
        <translation>カメラを合わせています: %1/%2</translation>
    </message>
    <message>
        <source>fitting the shape: round %1 of %2</source>
        <translation>形状を合わせています: ラウンド %1/%2</translation>
    </message>
    <message>
        <source>silhouette IoU %1 -&gt; %2, chamfer distance %3 -&gt; %4 px (%5 ms)
</source>
        <translation>シルエットIoU %1 -&gt; %2、チャンファー距離 %3 -&gt; %4 px（%5 ms）
</translation>
    </message>
    <message>
        <source>Writes the outline Fit to Drawing reads from a drawing; the options become the drawing&apos;s outline settings.</source>
        <translation>「参照画に合わせる」が参照画から読み取る輪郭を書き出します。オプションはその参照画の輪郭設定になります。</translation>
    </message>
    <message>
        <source>The drawing.</source>
        <translation>参照画。</translation>
    </message>
    <message>
        <source>Ink where the luminance is below T (0 black to 1 white); auto: Otsu&apos;s threshold.</source>
        <translation>輝度が T 未満の部分をインクとみなします（0 が黒、1 が白）。auto: 大津の手法によるしきい値。</translation>
    </message>
    <message>
        <source>Radius in pixels that closes gaps in open line art.</source>
        <translation>閉じていない線画のすき間を閉じる半径（ピクセル）。</translation>
    </message>
    <message>
        <source>Keep the holes inner lines enclose (default off).</source>
        <translation>内側の線が囲む穴を残します（既定: オフ）。</translation>
    </message>
    <message>
        <source>The SVG or PNG file to write.</source>
        <translation>書き出す SVG または PNG ファイル。</translation>
    </message>
    <message>
        <source>Fits a key&apos;s camera (--camera) and shape (--shape) to its drawing&apos;s outline, and saves the project.</source>
        <translation>キーのカメラ（--camera）と形状（--shape）を参照画の輪郭に合わせ、プロジェクトを保存します。</translation>
    </message>
    <message>
        <source>The key to fit.</source>
        <translation>合わせるキー。</translation>
    </message>
    <message>
        <source>Which of the key&apos;s linked drawings (default: the first).</source>
        <translation>キーにリンクされた参照画のうち、どれを使うか（既定: 最初の参照画）。</translation>
    </message>
    <message>
        <source>Fit the camera: rotation, position and field of view (orthographic: height).</source>
        <translation>カメラを合わせます: 回転、位置、画角（平行投影では高さ）。</translation>
    </message>
    <message>
        <source>Fit the key&apos;s shape at the drawing&apos;s frame (after the camera).</source>
        <translation>参照画のフレームでキーの形状を合わせます（カメラの後に行います）。</translation>
    </message>
    <message>
        <source>Only these painted faces may move (default: all).</source>
        <translation>これらのペイントした面だけを動かせるようにします（既定: すべて）。</translation>
    </message>
    <message>
        <source>The vertices of these faces stay put.</source>
        <translation>これらの面の頂点は動かしません。</translation>
    </message>
    <message>
        <source>Rounds of the shape fit at most (default 10).</source>
        <translation>形状合わせの最大ラウンド数（既定値 10）。</translation>
    </message>
    <message>
        <source>Fraction of the fitted deformation applied (default 1).</source>
        <translation>合わせ込んだ変形を適用する割合（既定値 1）。</translation>
    </message>
    <message>
        <source>--sharpness must be above 0 and at most %1</source>
        <translation>--sharpness には 0 より大きく %1 以下の値を指定してください</translation>
    </message>
    <message>
        <source>Blend sharpness alpha (above 0, at most 100).</source>
        <translation>ブレンドのシャープネス alpha（0 より大きく 100 以下）。</translation>
    </message>
    <message>
        <source>Keep the shape symmetric across the project&apos;s mirror plane.</source>
        <translation>プロジェクトのミラー平面に対して形状を対称に保ちます。</translation>
    </message>
    <message>
        <source>warning: vertex %1 has no mirror twin across the %2 plane; only its side moved</source>
        <translation>警告: 頂点 %1 には %2 平面をはさんだミラーの対応点がありません。その側だけが動きました</translation>
    </message>
    <message>
        <source>Move the mirror image too, across the plane perpendicular to that model axis through the model&apos;s centre; auto: the project&apos;s plane (detected on the model); off by default.</source>
        <translation>ミラー像も動かします。平面はモデルの中心を通りその軸に垂直です。auto: プロジェクトの平面（モデルから検出）。既定ではオフです。</translation>
    </message>
    <message>
        <source>Mirror plane: %1</source>
        <translation>ミラー平面: %1</translation>
    </message>
    <message>
        <source>warning: the selected faces have no mirror twins across the %1 plane; only their side was painted</source>
        <translation>警告: 選択した面には %1 平面をまたぐミラーの相手がありません。その側だけを塗りました</translation>
    </message>
    <message>
        <source>Also paint the faces&apos; mirror twins across this plane (auto: the project&apos;s; default off).</source>
        <translation>この平面をまたぐ面のミラーの相手も塗ります (auto: プロジェクトの平面。既定は off)。</translation>
    </message>
    <message>
        <source>--%1 must be auto, x, y, z or off, not “%2”</source>
        <translation>--%1 には auto、x、y、z、off のいずれかを指定してください (“%2” は使えません)</translation>
    </message>
    <message>
        <source>--out with --frames needs a # where the frame number goes, not “%1”</source>
        <translation>--frames と使う --out にはフレーム番号を入れる # が必要です (“%1” は使えません)</translation>
    </message>
    <message>
        <source>frame %1: %2 segments, %3 inside the window; depth error MSE %4 (%5 ms)</source>
        <translation>フレーム %1: セグメント %2 個、ウィンドウ内 %3 個。奥行き誤差 MSE %4 (%5 ms)</translation>
    </message>
    <message>
        <source>--csv goes with --frames</source>
        <translation>--csv は --frames と一緒に使います</translation>
    </message>
    <message>
        <source>--objective must be ratios, depth-error or both, not “%1”</source>
        <translation>--objective には ratios、depth-error、both のいずれかを指定してください (“%1” は使えません)</translation>
    </message>
    <message>
        <source>--start must be current or camera, not “%1”</source>
        <translation>--start には current または camera を指定してください (“%1” は使えません)</translation>
    </message>
    <message>
        <source>--falloff takes a ratio width in [0, 1] (0: discrete), not “%1”</source>
        <translation>--falloff には [0, 1] の比の幅を指定します (0: 離散)。“%1” は使えません</translation>
    </message>
    <message>
        <source>Frames to analyse, A-B inclusive, every STEP-th (default 1), through the shot camera unless a camera is given; --json lists them under &quot;frames&quot;, --out needs a # for the frame number.</source>
        <translation>解析するフレーム。A から B まで STEP おき (既定 1)。カメラの指定がなければショットカメラで見ます。--json は &quot;frames&quot; に一覧し、--out にはフレーム番号の # が必要です。</translation>
    </message>
    <message>
        <source>With --frames: a row per frame (frame, mse, rmse, segments, segments_in_window, milliseconds).</source>
        <translation>--frames と使い、フレームごとに 1 行 (frame, mse, rmse, segments, segments_in_window, milliseconds) を書きます。</translation>
    </message>
    <message>
        <source>Write the picture and the buffers (curvature, segment ids, depth, depth error, features, N.L and the light gradient) as EXR channels.</source>
        <translation>画像とバッファ (曲率、セグメント ID、奥行き、奥行き誤差、特徴、N.L、光の勾配) を EXR のチャンネルとして書き出します。</translation>
    </message>
    <message>
        <source>ratios (the thesis&apos;s, may raise the depth error), depth-error (a search minimising the depth error from the ratios&apos; answer) or both (the default: the ratios&apos; light unless it raises the depth error, else the best depth error met; never above the start&apos;s).</source>
        <translation>ratios (論文の方法。奥行き誤差が増えることがあります)、depth-error (ratios の答えから奥行き誤差を最小にする探索)、both (既定: 奥行き誤差を増やさない限り ratios の光、そうでなければ見つかった最良の奥行き誤差。開始時より悪くなりません)。</translation>
    </message>
    <message>
        <source>Start from the project&apos;s light (current, the default) or at the camera.</source>
        <translation>プロジェクトの光 (current、既定) またはカメラの位置から始めます。</translation>
    </message>
    <message>
        <source>Width of figure 5.8&apos;s linear fall-off outside the window (default 0.1; 0: discrete).</source>
        <translation>ウィンドウ外の図 5.8 の線形減衰の幅 (既定 0.1、0: 離散)。</translation>
    </message>
    <message>
        <source>key set needs --key and --mesh</source>
        <translation>key set には --key と --mesh が必要です</translation>
    </message>
    <message>
        <source>key set takes only --key, --mesh, --frame and --json</source>
        <translation>key set に使えるのは --key、--mesh、--frame、--json だけです</translation>
    </message>
    <message>
        <source>set: the key whose deformation is set.</source>
        <translation>set: 変形を設定するキー。</translation>
    </message>
    <message>
        <source>Adds a key viewpoint with its key deformation (add), or sets an existing key&apos;s deformation at a frame from a mesh, replacing one stored there (set).</source>
        <translation>キー変形付きのキー視点を追加する (add)、または既存のキーのあるフレームの変形をメッシュから設定し、そこにあるものを置き換えます (set)。</translation>
    </message>
    <message>
        <source>The action (add or set).</source>
        <translation>操作 (add または set)。</translation>
    </message>
    <message>
        <source>warning: the viewport&apos;s subdivision level %1 is above the render level %2; the viewport shows level %2</source>
        <translation>警告: ビューポートの細分化レベル %1 がレンダーのレベル %2 より上です。ビューポートはレベル %2 を表示します</translation>
    </message>
    <message>
        <source>Loop subdivision level that renders use, 0 (the control mesh) to 3.</source>
        <translation>レンダーで使う Loop 細分化レベル。0 (制御メッシュ) から 3。</translation>
    </message>
    <message>
        <source>The viewport&apos;s subdivision level: -1 follows the render level; a lower level is a speed setting.</source>
        <translation>ビューポートの細分化レベル。-1 はレンダーのレベルに従い、低いレベルは速度のための設定です。</translation>
    </message>
    <message>
        <source>--segments must be outside or all, not “%1”</source>
        <translation>--segments には outside または all を指定してください (“%1” は使えません)</translation>
    </message>
    <message>
        <source>Automatic per-segment offsets for the view: each segment of the depth analysis outside the ratio window 0.35-0.65 (or every segment, --segments all) gets the ratio 1 - Q.</source>
        <translation>視点ごとのセグメント別自動オフセット: 奥行き解析の各セグメントのうち比のウィンドウ 0.35-0.65 の外にあるもの (--segments all ではすべて) に比 1 - Q を与えます。</translation>
    </message>
    <message>
        <source>Which segments --auto solves: outside the window (the default, thesis 4.3) or all.</source>
        <translation>--auto が解くセグメント: ウィンドウの外 (既定、論文 4.3) またはすべて。</translation>
    </message>
    <message>
        <source>--%1 takes -1 (the render level) or a level from 0 to %2, not “%3”</source>
        <translation>--%1 には -1 (レンダーのレベル) または 0 から %2 のレベルを指定します (“%3” は使えません)</translation>
    </message>
    <message>
        <source>--%1 takes a subdivision level from 0 to %2, not “%3”</source>
        <translation>--%1 には 0 から %2 の細分化レベルを指定します (“%3” は使えません)</translation>
    </message>
    <message>
        <source>Loop subdivision level of this picture, 0 (the control mesh) to 3 (default: the project&apos;s render level).</source>
        <translation>この画像の Loop 細分化レベル。0 (制御メッシュ) から 3 (既定: プロジェクトのレンダーレベル)。</translation>
    </message>
    <message>
        <source>Apparent-ridge threshold for this picture: view-dependent curvature times the median edge length (default: the project&apos;s, 0.3 in new projects; lower draws more).</source>
        <translation>この画像の見かけの稜線のしきい値: 視点依存の曲率に辺の長さの中央値を掛けた値 (既定: プロジェクトの値、新規では 0.3。低いほど多く描きます)。</translation>
    </message>
    <message>
        <source>--max-turn takes degrees per frame in (0, 180], not “%1”</source>
        <translation>--max-turn は (0, 180] のフレームあたりの角度（度）を取ります。「%1」ではありません</translation>
    </message>
    <message>
        <source>frame %1: depth error MSE %2 -&gt; %3, turned %4° from the previous key%5</source>
        <translation>フレーム %1: 深度誤差 MSE %2 -&gt; %3、前のキーから %4° 回転%5</translation>
    </message>
    <message>
        <source> (limited)</source>
        <translation>（制限あり）</translation>
    </message>
    <message>
        <source>mean depth error MSE: %1 -&gt; %2; largest turn %3° between keys; %4 ms</source>
        <translation>平均深度誤差 MSE: %1 -&gt; %2、キー間の最大回転 %3°、%4 ms</translation>
    </message>
    <message>
        <source>the light track stays as it is</source>
        <translation>ライトトラックはそのままです</translation>
    </message>
    <message>
        <source>--max-turn goes with --frames</source>
        <translation>--max-turn は --frames と一緒に使います</translation>
    </message>
    <message>
        <source>Frame to optimise for (default 0); with a light track the light found is keyed there.</source>
        <translation>最適化するフレーム（既定値 0）。ライトトラックがある場合、見つかったライトはそのフレームにキーされます。</translation>
    </message>
    <message>
        <source>Optimise a light track: the light at frames A-B every STEP-th (default 1) through the shot camera, each frame starting from the previous one&apos;s light, saved as light keys.</source>
        <translation>ライトトラックを最適化します: ショットカメラを通したフレーム A-B の STEP ごと（既定値 1）のライトを、各フレームを前のフレームのライトから始めて求め、ライトキーとして保存します。</translation>
    </message>
    <message>
        <source>With --frames: the most a key turns from the previous one per frame, in degrees (default 3).</source>
        <translation>--frames と一緒に: キーが前のキーからフレームあたり回転できる最大角度（度、既定値 3）。</translation>
    </message>
    <message>
        <source>--format must be gltf, glb, pc2, obj-seq or usda, not “%1”</source>
        <translation>--format は gltf、glb、pc2、obj-seq、usda のいずれかです。「%1」ではありません</translation>
    </message>
    <message>
        <source>--subdivision applies to pc2, obj-seq and usda exports; glTF keeps the base model for its morph targets</source>
        <translation>--subdivision は pc2、obj-seq、usda の書き出しに使えます。glTF はモーフターゲットのためにベースモデルを保ちます</translation>
    </message>
    <message>
        <source>--blend-shapes applies to usda exports (glTF always holds the keys as morph targets)</source>
        <translation>--blend-shapes は usda の書き出しに使えます（glTF は常にキーをモーフターゲットとして持ちます）</translation>
    </message>
    <message>
        <source>--blend-shapes holds the keys on the base model and takes no --subdivision</source>
        <translation>--blend-shapes はキーをベースモデル上に持つため --subdivision を取りません</translation>
    </message>
    <message>
        <source>Exports the animation as seen through the camera path: a glTF scene with the keys as morph targets, a PC2 point cache, an OBJ per frame or a USD layer with time-sampled points and camera.</source>
        <translation>カメラパスから見たアニメーションを書き出します: キーをモーフターゲットとする glTF シーン、PC2 ポイントキャッシュ、フレームごとの OBJ、または時間サンプルされた点とカメラを持つ USD レイヤー。</translation>
    </message>
    <message>
        <source>gltf or glb (keys as morph targets, weights and camera animated), pc2 (point cache) or obj-seq (one OBJ per frame) or usda (USD text: time-sampled mesh and camera).</source>
        <translation>gltf または glb（キーをモーフターゲットとし、ウェイトとカメラをアニメーション）、pc2（ポイントキャッシュ）、obj-seq（フレームごとに 1 つの OBJ）、usda（USD テキスト: 時間サンプルされたメッシュとカメラ）。</translation>
    </message>
    <message>
        <source>Loop subdivision level of the exported surface, 0 to 3, for pc2, obj-seq and usda (default 0: the base model&apos;s vertices, in its order).</source>
        <translation>書き出す面の Loop 細分割レベル。0 から 3、pc2、obj-seq、usda 用（既定値 0: ベースモデルの頂点をその順序で）。</translation>
    </message>
    <message>
        <source>usda: the enabled keys as UsdSkel blend shapes with animated weights; the points then hold the shape without them.</source>
        <translation>usda: 有効なキーをアニメーションするウェイト付きの UsdSkel ブレンドシェイプとして書き出します。点はそれらを除いた形状になります。</translation>
    </message>
    <message>
        <source>an .svg output holds the lines pass; give --pass lines, not “%1”</source>
        <translation>.svg 出力はラインパスを持ちます。「%1」ではなく --pass lines を指定してください</translation>
    </message>
    <message>
        <source>an .svg output takes --stereo off, sbs, tb or anaglyph</source>
        <translation>.svg 出力は --stereo off、sbs、tb、anaglyph を取ります</translation>
    </message>
    <message>
        <source>--svg-tones needs an .svg output</source>
        <translation>--svg-tones には .svg 出力が必要です</translation>
    </message>
    <message>
        <source>--strokes needs the lines pass (--pass lines)</source>
        <translation>--strokes にはラインパス（--pass lines）が必要です</translation>
    </message>
    <message>
        <source>--strokes must end in .json, not “%1”</source>
        <translation>--strokes は .json で終わる必要があります。「%1」ではありません</translation>
    </message>
    <message>
        <source>a stereo render writes its strokes beside an .svg output only</source>
        <translation>ステレオレンダリングはストロークを .svg 出力の横にのみ書き出します</translation>
    </message>
    <message>
        <source>--out must end in .png, .exr, .tif, .jpg or .svg, not “%1”</source>
        <translation>--out は .png、.exr、.tif、.jpg、.svg のいずれかで終わる必要があります。「%1」ではありません</translation>
    </message>
    <message>
        <source>Output image (default: the project&apos;s name with .png); an .svg holds the lines pass as vector strokes.</source>
        <translation>出力画像（既定値: プロジェクト名に .png）。.svg はラインパスをベクターストロークとして持ちます。</translation>
    </message>
    <message>
        <source>With an .svg output: the tone regions as filled layers too.</source>
        <translation>.svg 出力で: トーン領域も塗りつぶしレイヤーとして書き出します。</translation>
    </message>
    <message>
        <source>With --pass lines: each stroke&apos;s points, widths, kind and depth as JSON too (a # is the frame number, as in --out).</source>
        <translation>--pass lines で: 各ストロークの点、幅、種類、深度も JSON で書き出します（# は --out と同じくフレーム番号）。</translation>
    </message>
    <message>
        <source>Light track: %1 keys</source>
        <translation>ライトトラック: %1 キー</translation>
    </message>
    <message>
        <source>--%1 takes segment numbers like 3,7, not “%2”</source>
        <translation>--%1 には 3,7 のようにセグメント番号を指定してください（「%2」は無効です）</translation>
    </message>
    <message>
        <source>--stroke takes two or more pixel positions X,Y,X,Y,..., not “%1”</source>
        <translation>--stroke には 2 つ以上のピクセル位置を X,Y,X,Y,... の形で指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>give one of --list, --merge A,B, --split S --stroke X,Y,X,Y, --release S or --clear</source>
        <translation>--list、--merge A,B、--split S --stroke X,Y,X,Y、--release S、--clear のいずれか 1 つを指定してください</translation>
    </message>
    <message>
        <source>--split and --stroke go together</source>
        <translation>--split と --stroke は一緒に指定してください</translation>
    </message>
    <message>
        <source>override %1	%2 faces</source>
        <translation>上書き %1	面 %2 個</translation>
    </message>
    <message>
        <source>no segment overrides</source>
        <translation>セグメントの上書きはありません</translation>
    </message>
    <message>
        <source>--split takes one segment number, not “%1”</source>
        <translation>--split にはセグメント番号を 1 つ指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>Clear Segment Overrides</source>
        <translation>セグメントの上書きを消去</translation>
    </message>
    <message>
        <source>Merge Segments</source>
        <translation>セグメントを結合</translation>
    </message>
    <message>
        <source>Release Segments</source>
        <translation>セグメントの上書きを解除</translation>
    </message>
    <message>
        <source>Split Segment</source>
        <translation>セグメントを分割</translation>
    </message>
    <message>
        <source>segments at frame %1: %2 -&gt; %3</source>
        <translation>フレーム %1 のセグメント: %2 -&gt; %3</translation>
    </message>
    <message>
        <source>List the override groups and their faces.</source>
        <translation>上書きのグループとその面を一覧表示します。</translation>
    </message>
    <message>
        <source>Make these segments (the numbers `analyze --json` gives for the same frame, camera and size) one.</source>
        <translation>これらのセグメント（同じフレーム、カメラ、サイズで `analyze --json` が出力する番号）を 1 つに結合します。</translation>
    </message>
    <message>
        <source>Split this segment in two along --stroke.</source>
        <translation>このセグメントを --stroke に沿って 2 つに分割します。</translation>
    </message>
    <message>
        <source>With --split: the stroke&apos;s points in the analysed picture&apos;s pixels (x right, y down).</source>
        <translation>--split で: ストロークの点。解析する画像のピクセル座標で指定します（x は右向き、y は下向き）。</translation>
    </message>
    <message>
        <source>Give these segments&apos; faces back to the analysis&apos;s own segmentation.</source>
        <translation>これらのセグメントの面を、解析本来のセグメント分けに戻します。</translation>
    </message>
    <message>
        <source>Remove every segment override.</source>
        <translation>セグメントの上書きをすべて削除します。</translation>
    </message>
    <message>
        <source>Frame the segments are numbered at (default 0).</source>
        <translation>セグメント番号を付けるフレーム（既定値 0）。</translation>
    </message>
    <message>
        <source>The segment brush: merges segments of the depth analysis, splits one along a stroke, or gives them back to the analysis, saved as per-face overrides.</source>
        <translation>セグメントブラシ: 奥行き解析のセグメントを結合する、1 つのセグメントをストロークに沿って分割する、または解析本来のセグメントに戻します。変更は面ごとの上書きとして保存されます。</translation>
    </message>
    <message>
        <source>--importance takes a value in [0, 1], not “%1”</source>
        <translation>--importance には [0, 1] の範囲の値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--strength takes a value in (0, 1], not “%1”</source>
        <translation>--strength には (0, 1] の範囲の値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>give one of --list, --add NAME, --subtract NAME or --importance V with a selection, or --remove NAME or --clear-importance</source>
        <translation>--list、面の選択を付けた --add NAME、--subtract NAME または --importance V、--remove NAME、--clear-importance のいずれかを指定してください</translation>
    </message>
    <message>
        <source>--strength goes with --importance</source>
        <translation>--strength は --importance と一緒に指定してください</translation>
    </message>
    <message>
        <source>Makes, lists and removes patches: named face sets that highlight layers are limited to; paints the faces&apos; importance (focal points) that the light optimisation weighs segments by.</source>
        <translation>パッチ（ハイライトレイヤーの表示範囲となる名前付きの面の集合）を作成・一覧・削除します。また、ライトの最適化でセグメントの重み付けに使う面の重要度（焦点）をペイントします。</translation>
    </message>
    <message>
        <source>Paint the selected faces&apos; importance towards V in [0, 1] (default of every face: 1); a segment&apos;s weight in the light optimisation is multiplied by its faces&apos; mean importance.</source>
        <translation>選んだ面の重要度を [0, 1] の範囲の値 V に近づけるようにペイントします（各面の既定値: 1）。ライトの最適化でのセグメントの重みには、その面の重要度の平均が掛けられます。</translation>
    </message>
    <message>
        <source>With --importance: the share of the way to V the faces go, in (0, 1] (default 1).</source>
        <translation>--importance で: 面の重要度を V までどれだけ近づけるかの割合、(0, 1]（既定値 1）。</translation>
    </message>
    <message>
        <source>Every face&apos;s importance back to 1.</source>
        <translation>すべての面の重要度を 1 に戻します。</translation>
    </message>
    <message>
        <source>Apparent ridges joined into smoothed snakes with short ones dropped (snakes), or as extracted (raw) (default: the project&apos;s, snakes in new projects).</source>
        <translation>見かけの稜線を平滑化したスネークにつなぎ、短いものを除く（snakes）か、抽出したままにする（raw）か（既定: プロジェクトの値、新規では snakes）。</translation>
    </message>
    <message>
        <source>Lowers the apparent-ridge threshold where the picture&apos;s stereo depth error is high, by 1 + K times the error over its root mean square (0 to 100; 0: one threshold everywhere; default: the project&apos;s).</source>
        <translation>画像の立体視の奥行き誤差が大きい所で、見かけの稜線のしきい値を 1 + K ×（誤差 ÷ 誤差の二乗平均平方根）で割って下げます（0～100。0: どこでも同じしきい値。既定: プロジェクトの値）。</translation>
    </message>
    <message>
        <source>--ridges takes snakes or raw, not “%1”</source>
        <translation>--ridges には snakes または raw を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--ridge-depth takes a number from 0 to 100, not “%1”</source>
        <translation>--ridge-depth には 0～100 の数値を指定してください（「%1」は無効です）</translation>
    </message>
    <message>
        <source>--size must be between 16x16 and 8192x8192 for --auto, not %1x%2</source>
        <translation>--auto の --size は 16x16 から 8192x8192 の間にしてください (%1x%2 は範囲外です)</translation>
    </message>
    <message>
        <source>(unsaved document)</source>
        <translation>(未保存のドキュメント)</translation>
    </message>
</context>
<context>
    <name>celform::app::ExportDialog</name>
    <message>
        <source>glTF 2.0 (.gltf): keys as morph targets, weights and camera animated</source>
        <translation>glTF 2.0 (.gltf): キーをモーフターゲットにし、ウェイトとカメラをアニメーション</translation>
    </message>
    <message>
        <source>glTF 2.0 binary (.glb)</source>
        <translation>glTF 2.0 バイナリ (.glb)</translation>
    </message>
    <message>
        <source>PC2 point cache (.pc2): the shape at every frame</source>
        <translation>PC2 ポイントキャッシュ (.pc2): 各フレームの形状</translation>
    </message>
    <message>
        <source>OBJ sequence: one .obj per frame</source>
        <translation>OBJ 連番: フレームごとに 1 つの .obj</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>エクスポート</translation>
    </message>
    <message>
        <source>to</source>
        <translation>～</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>形式(&amp;F):</translation>
    </message>
    <message>
        <source>F&amp;rames:</source>
        <translation>フレーム(&amp;R):</translation>
    </message>
    <message>
        <source>F&amp;ile:</source>
        <translation>ファイル(&amp;I):</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>エクスポート(&amp;E)</translation>
    </message>
    <message>
        <source>The file must end in .%1 for this format.</source>
        <translation>この形式ではファイル名を .%1 で終える必要があります。</translation>
    </message>
    <message>
        <source>USD (.usda): time-sampled points, normals and camera</source>
        <translation>USD (.usda): 時間サンプルされた点、法線、カメラ</translation>
    </message>
    <message>
        <source>&amp;Keys as blend shapes (animated weights)</source>
        <translation>キーをブレンドシェイプとして(&amp;K)（アニメーションするウェイト）</translation>
    </message>
    <message>
        <source>USD: the enabled keys as UsdSkel blend shapes whose weights follow the camera path; the points then hold the shape without them</source>
        <translation>USD: 有効なキーを、ウェイトがカメラパスに従う UsdSkel ブレンドシェイプとして書き出します。点はそれらを除いた形状になります</translation>
    </message>
</context>
<context>
    <name>celform::app::ExportRunner</name>
    <message>
        <source>Export</source>
        <translation>エクスポート</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>%1 をエクスポートしています…</translation>
    </message>
    <message>
        <source>%1: not enough memory to export</source>
        <translation>%1: エクスポートするメモリが足りません</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>エクスポートに失敗しました</translation>
    </message>
    <message>
        <source>The export could not be finished.</source>
        <translation>エクスポートを完了できませんでした。</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>エクスポートに失敗しました: %1</translation>
    </message>
    <message>
        <source>Export cancelled.</source>
        <translation>エクスポートをキャンセルしました。</translation>
    </message>
    <message>
        <source>Exported %L1 frames to %2</source>
        <translation>%L1 フレームを %2 にエクスポートしました</translation>
    </message>
</context>
<context>
    <name>celform::app::FirstStepsHint</name>
    <message>
        <source>Start with a model: File ▸ New from Mesh (Ctrl+N), or open a project (Ctrl+O). Help ▸ Getting Started walks through the rest.</source>
        <translation>まずモデルから: ファイル ▸ メッシュから新規作成（Ctrl+N）、またはプロジェクトを開く（Ctrl+O）。続きはヘルプ ▸ はじめにで案内します。</translation>
    </message>
    <message>
        <source>Import a drawing of the model sheet: File ▸ Import Drawing (Ctrl+Shift+I), or drop an image here.</source>
        <translation>設定画の絵を読み込みます: ファイル ▸ 絵の読み込み（Ctrl+Shift+I）、またはここに画像をドロップしてください。</translation>
    </message>
    <message>
        <source>Select a drawing in the Scene panel and press Align to Drawing; then Create Key from Drawing.</source>
        <translation>シーンパネルで絵を選んで「絵に合わせる」を押し、次に「絵からキーを作成」を押してください。</translation>
    </message>
    <message>
        <source>Press Space: the model changes shape with the view to match its drawings. Click a key in the Scene panel to see its drawing.</source>
        <translation>Space キーを押してください: モデルは参照画に合うよう視点に応じて形を変えます。シーンパネルでキーをクリックすると、その参照画が表示されます。</translation>
    </message>
    <message>
        <source>Press Align to Drawing in the Properties panel and move the camera until the model matches the drawing.</source>
        <translation>プロパティパネルの「参照画に位置合わせ」を押し、モデルが参照画に合うまでカメラを動かしてください。</translation>
    </message>
    <message>
        <source>The camera matches the drawing: press Create Key from Drawing in the Properties panel.</source>
        <translation>カメラが参照画に合いました: プロパティパネルの「参照画からキーを作成」を押してください。</translation>
    </message>
    <message>
        <source>If Alt + drag moves the window instead of the view, choose Blender navigation in Edit ▸ Preferences: it needs no Alt.</source>
        <translation>Alt + ドラッグでビューではなくウィンドウが動く場合は、「編集」▸「環境設定」で Blender のナビゲーションを選んでください。Alt を使いません。</translation>
    </message>
</context>
<context>
    <name>celform::app::FitActions</name>
    <message>
        <source>silhouette IoU %1 → %2, chamfer distance %3 → %4 px</source>
        <translation>シルエットIoU %1 → %2、チャンファー距離 %3 → %4 px</translation>
    </message>
    <message>
        <source>Camera fitted to “%1”: %2.</source>
        <translation>カメラを「%1」に合わせました: %2。</translation>
    </message>
    <message>
        <source>The key “%1” already meets its drawing: nothing moved.</source>
        <translation>キー「%1」はすでに参照画と一致しています。何も動かしていません。</translation>
    </message>
    <message numerus="yes">
        <source>Shape of “%1” fitted: %2; %n vertices moved.</source>
        <translation>
            <numerusform>「%1」の形状を合わせました: %2。%n 個の頂点を動かしました。</numerusform>
        </translation>
    </message>
    <message>
        <source>Fit &amp;Camera to Drawing</source>
        <translation>カメラを参照画に合わせる(&amp;C)</translation>
    </message>
    <message>
        <source>Find the camera for which the model&apos;s silhouette meets the drawing&apos;s outline, starting from the drawing&apos;s alignment: the drawing&apos;s camera and its key&apos;s (one undo step)</source>
        <translation>参照画の位置合わせを出発点として、モデルのシルエットが参照画の輪郭と一致するカメラを求めます。参照画のカメラとそのキーのカメラが対象です（1 回の「元に戻す」で戻せます）</translation>
    </message>
    <message>
        <source>Fit &amp;Shape to Drawing</source>
        <translation>形状を参照画に合わせる(&amp;S)</translation>
    </message>
    <message>
        <source>Deform the key at its drawing&apos;s frame until its silhouette meets the drawing&apos;s outline, with the Properties panel&apos;s region, pins and strength and the brush&apos;s X mirror (one undo step)</source>
        <translation>参照画のフレームで、シルエットが参照画の輪郭と一致するまでキーを変形します。「プロパティ」パネルの領域、ピン、強さと、ブラシの X ミラーを使います（1 回の「元に戻す」で戻せます）</translation>
    </message>
    <message>
        <source>Fit to &amp;Drawing</source>
        <translation>参照画に合わせる(&amp;D)</translation>
    </message>
    <message>
        <source>Not enough memory to fit the model to the drawing.</source>
        <translation>モデルを参照画に合わせるためのメモリが足りません。</translation>
    </message>
    <message>
        <source>Fit Camera to Drawing</source>
        <translation>カメラを参照画に合わせる</translation>
    </message>
    <message>
        <source>Fitting the camera to the drawing&apos;s outline…</source>
        <translation>カメラを参照画の輪郭に合わせています…</translation>
    </message>
    <message>
        <source>Fitting the camera: step %1 of %2…</source>
        <translation>カメラを合わせています: ステップ %1/%2…</translation>
    </message>
    <message>
        <source>Fit Shape to Drawing</source>
        <translation>形状を参照画に合わせる</translation>
    </message>
    <message>
        <source>Fitting the key&apos;s shape to the drawing&apos;s outline…</source>
        <translation>キーの形状を参照画の輪郭に合わせています…</translation>
    </message>
    <message>
        <source>Fitting the shape: round %1 of %2…</source>
        <translation>形状を合わせています: ラウンド %1/%2…</translation>
    </message>
</context>
<context>
    <name>celform::app::FocalPointActions</name>
    <message>
        <source>&amp;Focal Points</source>
        <translation>焦点(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Paint Focal Points</source>
        <translation>焦点をペイント(&amp;P)</translation>
    </message>
    <message>
        <source>Patch brush in importance mode: drag takes the faces towards the importance, Ctrl+drag back towards 1; the light optimisation weighs each segment by its faces&apos; mean importance (thesis 6.2)</source>
        <translation>重要度モードのパッチブラシ: ドラッグで面を指定の重要度に近づけ、Ctrl+ドラッグで 1 に戻します。ライトの最適化では、各セグメントをその面の重要度の平均で重み付けします（論文 6.2）</translation>
    </message>
    <message>
        <source>&amp;Importance…</source>
        <translation>重要度(&amp;I)…</translation>
    </message>
    <message>
        <source>The importance a drag paints towards: 0 leaves the faces out of the light optimisation, 1 counts them fully</source>
        <translation>ドラッグで近づける重要度: 0 ではその面をライトの最適化から外し、1 では完全に考慮します</translation>
    </message>
    <message>
        <source>Focal Point Importance</source>
        <translation>焦点の重要度</translation>
    </message>
    <message>
        <source>Importance painted (0 to 1):</source>
        <translation>ペイントする重要度（0～1）:</translation>
    </message>
    <message>
        <source>S&amp;trength…</source>
        <translation>強さ(&amp;T)…</translation>
    </message>
    <message>
        <source>The share of the way to the importance one drag takes each face</source>
        <translation>1 回のドラッグで各面を指定の重要度にどれだけ近づけるかの割合</translation>
    </message>
    <message>
        <source>Focal Point Strength</source>
        <translation>焦点ペイントの強さ</translation>
    </message>
    <message>
        <source>Share of the way one drag goes (0.01 to 1):</source>
        <translation>1 回のドラッグで近づける割合（0.01～1）:</translation>
    </message>
    <message>
        <source>&amp;Clear Focal Points</source>
        <translation>焦点を消去(&amp;C)</translation>
    </message>
    <message>
        <source>Every face&apos;s importance back to 1</source>
        <translation>すべての面の重要度を 1 に戻します</translation>
    </message>
    <message>
        <source>Segment &amp;Brush</source>
        <translation>セグメントブラシ(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Merge Segments</source>
        <translation>セグメントを結合(&amp;M)</translation>
    </message>
    <message>
        <source>Click a segment of the depth analysis, then another: they become one segment</source>
        <translation>奥行き解析のセグメントをクリックし、続けて別のセグメントをクリックすると、1 つのセグメントになります</translation>
    </message>
    <message>
        <source>&amp;Split Segment</source>
        <translation>セグメントを分割(&amp;S)</translation>
    </message>
    <message>
        <source>Drag across a segment of the depth analysis: it becomes two, one on each side of the drag</source>
        <translation>奥行き解析のセグメントを横切ってドラッグすると、ドラッグの両側で 2 つのセグメントに分かれます</translation>
    </message>
    <message>
        <source>&amp;Clear Segment Overrides</source>
        <translation>セグメントの上書きを消去(&amp;C)</translation>
    </message>
    <message>
        <source>Every face back to the segments the analysis finds</source>
        <translation>すべての面を解析で求めたセグメントに戻します</translation>
    </message>
    <message>
        <source>Clear Segment Overrides</source>
        <translation>セグメントの上書きを消去</translation>
    </message>
</context>
<context>
    <name>celform::app::GettingStarted</name>
    <message>
        <source>Getting Started</source>
        <translation>はじめに</translation>
    </message>
</context>
<context>
    <name>celform::app::JobRunner</name>
    <message>
        <source>Not enough memory.</source>
        <translation>メモリが不足しています。</translation>
    </message>
</context>
<context>
    <name>celform::app::LightOptimisationRunner</name>
    <message>
        <source>Optimise Light for Stereo</source>
        <translation>ステレオ用にライトを最適化</translation>
    </message>
    <message>
        <source>Analysing the picture (%1 × %2)…</source>
        <translation>画像を解析中（%1 × %2）…</translation>
    </message>
    <message>
        <source>Not enough memory to analyse %1 × %2 pixels</source>
        <translation>%1 × %2 ピクセルを解析するメモリが足りません</translation>
    </message>
    <message>
        <source>Moving the light: iteration %1 of %2…</source>
        <translation>ライトを移動中: 反復 %1 / %2…</translation>
    </message>
    <message>
        <source>Analysing the picture with the new light…</source>
        <translation>新しいライトで画像を解析中…</translation>
    </message>
    <message>
        <source>Light optimised: the segments&apos; bright/dark ratios are %1 % closer to the window (distance %2 → %3); %4 of %5 segments inside it (before: %6); depth error MSE %7 → %8 (%9 ms)</source>
        <translation>ライトを最適化しました: セグメントの明暗比がウィンドウに %1 % 近づきました（距離 %2 → %3）。ウィンドウ内のセグメント %5 個中 %4 個（以前: %6）。奥行き誤差 MSE %7 → %8（%9 ms）</translation>
    </message>
    <message>
        <source>Fewer segments are inside the window than before (%1 → %2 of %3): the ratios came closer overall, but some that were inside left it. Undo if those mattered, or weight the segments by area in the Depth tab.</source>
        <translation>ウィンドウ内のセグメントが以前より減りました（%3 個中 %1 → %2）: 比は全体として近づきましたが、内側にあったものの一部が外れました。それらが重要なら元に戻すか、奥行きタブでセグメントを面積で重み付けしてください。</translation>
    </message>
    <message>
        <source>The segments&apos; ratios improved but the depth error rose: try another start light (move it, then optimise again) or a more lenient window in the Depth tab.</source>
        <translation>セグメントの比は改善しましたが奥行き誤差が増えました: 別の開始ライトを試す（ライトを動かしてから再度最適化する）か、奥行きタブでより緩いウィンドウを選んでください。</translation>
    </message>
    <message>
        <source>; the ratios&apos; light raised the depth error, so a search kept the light with the lowest depth error it met</source>
        <translation>。ratios の光では奥行き誤差が増えたため、探索で見つかった奥行き誤差が最小の光を採用しました</translation>
    </message>
</context>
<context>
    <name>celform::app::LightTrackRunner</name>
    <message numerus="yes">
        <source>Light track: %n frame(s) keyed; mean depth error MSE %1 → %2; largest turn between keys %3° (%4 ms)</source>
        <translation>
            <numerusform>ライトトラック: %n フレームをキー。平均深度誤差 MSE %1 → %2、キー間の最大回転 %3°（%4 ms）</numerusform>
        </translation>
    </message>
    <message>
        <source>Optimise Light Along Shot</source>
        <translation>ショット全体でライトを最適化</translation>
    </message>
    <message numerus="yes">
        <source>Optimising the light at %n frame(s)…</source>
        <translation>
            <numerusform>%n フレームでライトを最適化しています…</numerusform>
        </translation>
    </message>
    <message>
        <source>Optimising the light at frame %1 (%2 of %3)…</source>
        <translation>フレーム %1 でライトを最適化しています（%3 中 %2）…</translation>
    </message>
    <message>
        <source>Not enough memory to analyse %1 × %2 pixels</source>
        <translation>%1 × %2 ピクセルを解析するメモリが足りません</translation>
    </message>
    <message>
        <source>the project</source>
        <translation>プロジェクト</translation>
    </message>
</context>
<context>
    <name>celform::app::MainWindow</name>
    <message>
        <source>Not enough memory.</source>
        <translation>メモリが不足しています。</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>準備完了</translation>
    </message>
    <message>
        <source>Autosaved a recovery copy</source>
        <translation>復旧用のコピーを自動保存しました</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>自動保存に失敗しました: %1</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>シーン</translation>
    </message>
    <message>
        <source>&lt;Opened project&gt;</source>
        <translation>&lt;プロジェクトを開いた状態&gt;</translation>
    </message>
    <message>
        <source>Every edit of the project; click an entry to go back to it</source>
        <translation>プロジェクトに対するすべての編集です。項目をクリックするとその時点に戻ります</translation>
    </message>
    <message>
        <source>History</source>
        <translation>履歴</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>プロパティ</translation>
    </message>
    <message>
        <source>&amp;New from Mesh…</source>
        <translation>メッシュから新規作成(&amp;N)…</translation>
    </message>
    <message>
        <source>Start a new project on a base model (OBJ, PLY, STL, OFF, glTF)</source>
        <translation>ベースモデル（OBJ、PLY、STL、OFF、glTF）から新しいプロジェクトを開始します</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <source>Open a Celform project</source>
        <translation>Celform プロジェクトを開きます</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation>プロジェクトを保存します</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>名前を付けて保存(&amp;A)…</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>プロジェクトに新しい名前を付けて保存します</translation>
    </message>
    <message>
        <source>Import &amp;Mesh…</source>
        <translation>メッシュをインポート(&amp;M)…</translation>
    </message>
    <message>
        <source>Replace the base model by a mesh file with the same vertex order</source>
        <translation>頂点順序が同じメッシュファイルでベースモデルを置き換えます</translation>
    </message>
    <message>
        <source>Import &amp;Drawing…</source>
        <translation>参照画をインポート(&amp;D)…</translation>
    </message>
    <message>
        <source>Add a reference drawing (PNG, JPEG, TIFF, EXR, PSD, SVG) to the model sheet</source>
        <translation>設定画に参照画（PNG、JPEG、TIFF、EXR、PSD、SVG）を追加します</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <source>Quit Celform</source>
        <translation>Celform を終了します</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>やり直し(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>削除(&amp;D)</translation>
    </message>
    <message>
        <source>Remove the selected drawing or key viewpoint</source>
        <translation>選択した参照画またはキー視点を削除します</translation>
    </message>
    <message>
        <source>&amp;Frame All</source>
        <translation>全体を表示(&amp;F)</translation>
    </message>
    <message>
        <source>Fit the whole model in the viewport</source>
        <translation>モデル全体をビューポートに収めます</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>平行投影(&amp;O)</translation>
    </message>
    <message>
        <source>Switch between perspective and orthographic projection</source>
        <translation>透視投影と平行投影を切り替えます</translation>
    </message>
    <message>
        <source>&amp;About Celform</source>
        <translation>Celform について(&amp;A)</translation>
    </message>
    <message>
        <source>Version and licence</source>
        <translation>バージョンとライセンス</translation>
    </message>
    <message>
        <source>About Celform</source>
        <translation>Celform について</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Celform %1&lt;/h3&gt;&lt;p&gt;View-dependent models, shaped highlights and stereo-aware toon rendering for cel animation.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Celform %1&lt;/h3&gt;&lt;p&gt;セルアニメーションのための視点依存モデル、形状を調整できるハイライト、立体視に対応したトゥーンレンダリング。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Qt について(&amp;Q)</translation>
    </message>
    <message>
        <source>Qt version and licence</source>
        <translation>Qt のバージョンとライセンス</translation>
    </message>
    <message>
        <source>&amp;Navigation</source>
        <translation>ナビゲーション(&amp;N)</translation>
    </message>
    <message>
        <source>Mouse and keyboard navigation in the viewport</source>
        <translation>ビューポートでのマウスとキーボードによる操作</translation>
    </message>
    <message>
        <source>Viewport navigation</source>
        <translation>ビューポートの操作</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + left drag&lt;/b&gt;, &lt;b&gt;middle drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;orbit&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + middle drag&lt;/b&gt;, &lt;b&gt;Shift + middle drag&lt;/b&gt;&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + right drag&lt;/b&gt;, &lt;b&gt;Ctrl + middle drag&lt;/b&gt;, &lt;b&gt;wheel&lt;/b&gt;&lt;/td&gt;&lt;td&gt;dolly&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;frame all&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;front view&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;perspective / orthographic&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + 左ボタンドラッグ&lt;/b&gt;、&lt;b&gt;中ボタンドラッグ&lt;/b&gt;&lt;/td&gt;&lt;td&gt;回転（オービット）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + 中ボタンドラッグ&lt;/b&gt;、&lt;b&gt;Shift + 中ボタンドラッグ&lt;/b&gt;&lt;/td&gt;&lt;td&gt;パン&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt + 右ボタンドラッグ&lt;/b&gt;、&lt;b&gt;Ctrl + 中ボタンドラッグ&lt;/b&gt;、&lt;b&gt;ホイール&lt;/b&gt;&lt;/td&gt;&lt;td&gt;ドリー&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;全体を表示&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Home&lt;/b&gt;&lt;/td&gt;&lt;td&gt;正面ビュー&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;透視投影 / 平行投影&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近使ったプロジェクト(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <source>%1[*] — Celform</source>
        <translation>%1[*] — Celform</translation>
    </message>
    <message>
        <source>No base model</source>
        <translation>ベースモデルなし</translation>
    </message>
    <message>
        <source>%1 vertices · %2 triangles · %3 drawings · %4 keys</source>
        <translation>頂点 %1 · 三角形 %2 · 参照画 %3 · キー %4</translation>
    </message>
    <message>
        <source>Celform</source>
        <translation>Celform</translation>
    </message>
    <message>
        <source>%1 loaded with warnings: %2</source>
        <translation>%1 を読み込みました（警告あり）: %2</translation>
    </message>
    <message>
        <source>%1: not a project, mesh or image file Celform can read</source>
        <translation>%1: Celform で読み込めるプロジェクト、メッシュ、画像のいずれのファイルでもありません</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>%1 を開いています…</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>%1 を読み込んでいます…</translation>
    </message>
    <message>
        <source>Loaded %1</source>
        <translation>%1 を読み込みました</translation>
    </message>
    <message>
        <source>Added drawing %1</source>
        <translation>参照画 %1 を追加しました</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>プロジェクトを保存</translation>
    </message>
    <message>
        <source>Celform projects (*.celform)</source>
        <translation>Celform プロジェクト (*.celform)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存の変更</translation>
    </message>
    <message>
        <source>The project “%1” has unsaved changes. Save them first?</source>
        <translation>プロジェクト「%1」には保存されていない変更があります。先に保存しますか？</translation>
    </message>
    <message>
        <source>New Project from Mesh</source>
        <translation>メッシュから新規プロジェクト</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>プロジェクトを開く</translation>
    </message>
    <message>
        <source>Import Mesh</source>
        <translation>メッシュをインポート</translation>
    </message>
    <message>
        <source>Import Drawings</source>
        <translation>参照画をインポート</translation>
    </message>
    <message>
        <source>No recent projects</source>
        <translation>最近使ったプロジェクトはありません</translation>
    </message>
    <message>
        <source>&amp;Clear List</source>
        <translation>一覧をクリア(&amp;C)</translation>
    </message>
    <message>
        <source>an untitled project</source>
        <translation>無題のプロジェクト</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>未保存の作業の復旧</translation>
    </message>
    <message>
        <source>Celform did not close normally. A recovery copy of %1 from %2 was found.

Recover it now?</source>
        <translation>Celform は正常に終了しませんでした。%2 に保存された %1 の復旧用コピーが見つかりました。

今すぐ復旧しますか？</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>復旧(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Keep for Later</source>
        <translation>残しておく(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;Discard…</source>
        <translation>破棄(&amp;D)…</translation>
    </message>
    <message>
        <source>Recovered %1; save it to keep it</source>
        <translation>%1 を復旧しました。残すには保存してください</translation>
    </message>
    <message>
        <source>Discard recovery copy</source>
        <translation>復旧用コピーの破棄</translation>
    </message>
    <message>
        <source>Delete the recovery copy of %1 for good?</source>
        <translation>%1 の復旧用コピーを完全に削除しますか？</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>メイン</translation>
    </message>
    <message>
        <source>Messages of this session: files opened and saved, import warnings, errors</source>
        <translation>このセッションのメッセージ: 開いた/保存したファイル、インポート時の警告、エラー</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>ログ</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>エラー</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>情報</translation>
    </message>
    <message>
        <source>Key created: select Edit Key with the Brush to deform it</source>
        <translation>キーを作成しました。変形するには「ブラシでキーを編集」を選択してください</translation>
    </message>
    <message>
        <source>Viewing Sphere</source>
        <translation>視点球</translation>
    </message>
    <message>
        <source>The view-dependent shape for the main camera, seen from this camera of its own</source>
        <translation>メインカメラに対する視点依存形状を、このビュー独自のカメラから表示します</translation>
    </message>
    <message>
        <source>Observer</source>
        <translation>観察ビュー</translation>
    </message>
    <message>
        <source>&amp;Preview View-Dependent Shape</source>
        <translation>視点依存形状をプレビュー(&amp;P)</translation>
    </message>
    <message>
        <source>Show the blend of the keys for the current camera, updated while orbiting</source>
        <translation>現在のカメラに対するキーのブレンド結果を表示します（回転中も更新されます）</translation>
    </message>
    <message>
        <source>&amp;Navigate Only</source>
        <translation>ナビゲーションのみ(&amp;N)</translation>
    </message>
    <message>
        <source>Create Key from &amp;View</source>
        <translation>現在のビューからキーを作成(&amp;V)</translation>
    </message>
    <message>
        <source>Make a key viewpoint seen from the current camera, starting as a copy of the base model</source>
        <translation>現在のカメラから見たキー視点を作成します。初期形状はベースモデルのコピーです</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>キー</translation>
    </message>
    <message>
        <source>Look</source>
        <translation>ルック</translation>
    </message>
    <message>
        <source>Show Cartoon &amp;Look</source>
        <translation>アニメ調のルックを表示(&amp;L)</translation>
    </message>
    <message>
        <source>Shade the model with the document&apos;s look as the renderer does (off: neutral clay for modelling); Ctrl+drag the light gizmo to move the key light</source>
        <translation>レンダラーと同じように、プロジェクトのルックでモデルをシェーディングします（オフ: モデリング用のニュートラルなクレイ表示）。ライトのギズモを Ctrl + ドラッグするとキーライトを移動できます</translation>
    </message>
    <message>
        <source>Stereo &amp;Review</source>
        <translation>ステレオレビュー(&amp;R)</translation>
    </message>
    <message>
        <source>Full-screen stereo review of the look: turntable, keys&apos; cameras, stereo modes (H for help)</source>
        <translation>ルックをフルスクリーンのステレオ表示でレビューします: ターンテーブル、各キーのカメラ、ステレオモード（H でヘルプ）</translation>
    </message>
    <message>
        <source>Highlights</source>
        <translation>ハイライト</translation>
    </message>
    <message>
        <source>Set &amp;Render Camera from View</source>
        <translation>現在の視点をレンダーカメラに設定(&amp;R)</translation>
    </message>
    <message>
        <source>Make the current view the project&apos;s render camera: celform render looks through it unless given a camera</source>
        <translation>現在の視点をプロジェクトのレンダーカメラにします: celform render はカメラの指定がなければこのカメラで描きます</translation>
    </message>
    <message>
        <source>The render camera is the current view.</source>
        <translation>レンダーカメラを現在の視点にしました。</translation>
    </message>
    <message>
        <source>View Through Render &amp;Camera</source>
        <translation>レンダーカメラから見る(&amp;C)</translation>
    </message>
    <message>
        <source>Look through the project&apos;s render camera</source>
        <translation>プロジェクトのレンダーカメラから見ます</translation>
    </message>
    <message>
        <source>No render camera yet: set one from a view first (Ctrl+Alt+0).</source>
        <translation>レンダーカメラがまだありません。まず視点から設定してください（Ctrl+Alt+0）。</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>正面(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>背面(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>右(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>左(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>上(&amp;T)</translation>
    </message>
    <message>
        <source>B&amp;ottom</source>
        <translation>下(&amp;O)</translation>
    </message>
    <message>
        <source>Look at the model from this side, framed</source>
        <translation>この方向からモデルを見て、全体を収めます</translation>
    </message>
    <message>
        <source>&amp;Off (Mono)</source>
        <translation>オフ（モノラル）(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Anaglyph (Red/Cyan)</source>
        <translation>アナグリフ（赤/シアン）(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Dubois Anaglyph</source>
        <translation>Dubois アナグリフ(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Half-Colour Anaglyph</source>
        <translation>ハーフカラー アナグリフ(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Side by Side</source>
        <translation>サイドバイサイド(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Top/Bottom</source>
        <translation>トップアンドボトム(&amp;T)</translation>
    </message>
    <message>
        <source>Show the viewport in this stereo mode, with the look&apos;s interocular and convergence</source>
        <translation>このステレオ方式でビューポートを表示します（ルックの眼間距離と輻輳を使用）</translation>
    </message>
    <message>
        <source>Toggle Stereo &amp;Preview</source>
        <translation>ステレオプレビューの切り替え(&amp;P)</translation>
    </message>
    <message>
        <source>Switch the viewport between mono and the last stereo mode (anaglyph at first)</source>
        <translation>ビューポートをモノラルと最後のステレオ方式（最初はアナグリフ）で切り替えます</translation>
    </message>
    <message>
        <source>Drawing &amp;Outline Only</source>
        <translation>絵の輪郭線のみ(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Getting Started</source>
        <translation>はじめに(&amp;G)</translation>
    </message>
    <message>
        <source>A short illustrated guide: from the sample to a view-dependent model</source>
        <translation>図解の短い手引き: サンプルから視点依存モデルまで</translation>
    </message>
    <message>
        <source>View &amp;From</source>
        <translation>視点プリセット(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Stereo Preview</source>
        <translation>ステレオプレビュー(&amp;S)</translation>
    </message>
    <message>
        <source>Untitled project</source>
        <translation>無題のプロジェクト</translation>
    </message>
    <message>
        <source>&amp;Render Image…</source>
        <translation>画像をレンダー(&amp;R)…</translation>
    </message>
    <message>
        <source>Render the current frame to an image file, as celform render does</source>
        <translation>現在のフレームを画像ファイルにレンダーします（celform render と同じ処理）</translation>
    </message>
    <message>
        <source>Render Se&amp;quence…</source>
        <translation>連番をレンダー(&amp;Q)…</translation>
    </message>
    <message>
        <source>Render a range of frames to numbered image files</source>
        <translation>フレーム範囲を連番の画像ファイルにレンダーします</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>キーボードショートカット(&amp;K)</translation>
    </message>
    <message>
        <source>Every keyboard shortcut of the editor, searchable</source>
        <translation>エディターのすべてのキーボードショートカット（検索できます）</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>環境設定(&amp;P)…</translation>
    </message>
    <message>
        <source>Navigation, autosave, undo steps, language, new projects&apos; look and keyboard shortcuts</source>
        <translation>ナビゲーション、自動保存、取り消しの回数、言語、新規プロジェクトのルック、キーボードショートカット</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>元に戻す</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>やり直し</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>奥行き</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>なし(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Segments</source>
        <translation>セグメント(&amp;S)</translation>
    </message>
    <message>
        <source>Gaussian &amp;Curvature</source>
        <translation>ガウス曲率(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Depth Error</source>
        <translation>奥行き誤差(&amp;D)</translation>
    </message>
    <message>
        <source>Show this depth analysis over the viewport (Depth dock)</source>
        <translation>この奥行き解析をビューポートに重ねて表示します（奥行きドック）</translation>
    </message>
    <message>
        <source>Next Depth &amp;Overlay</source>
        <translation>次の奥行きオーバーレイ(&amp;O)</translation>
    </message>
    <message>
        <source>Cycle the viewport&apos;s depth overlay: none, segments, Gaussian curvature, depth error</source>
        <translation>ビューポートの奥行きオーバーレイを切り替えます: なし、セグメント、ガウス曲率、奥行き誤差</translation>
    </message>
    <message>
        <source>&amp;Depth Overlay</source>
        <translation>奥行きオーバーレイ(&amp;D)</translation>
    </message>
    <message>
        <source>Optimise &amp;Light for Stereo</source>
        <translation>ステレオ用にライトを最適化(&amp;L)</translation>
    </message>
    <message>
        <source>Move the key light so that every segment of the Depth tab gets a shading line across it: the depth error falls (one undo step; method in the Depth tab)</source>
        <translation>「奥行き」タブの各セグメントに陰影の境界線がかかるようにキーライトを動かし、奥行き誤差を減らします（1 回の「元に戻す」で戻せます。手法は「奥行き」タブで選びます）</translation>
    </message>
    <message>
        <source>&amp;Look</source>
        <translation>ルック(&amp;L)</translation>
    </message>
    <message>
        <source>Open a model first: the light is optimised for the picture of a model.</source>
        <translation>先にモデルを開いてください。ライトはモデルの画像に対して最適化されます。</translation>
    </message>
    <message>
        <source>Light optimisation cancelled: the light is unchanged.</source>
        <translation>ライトの最適化をキャンセルしました。ライトは変更されていません。</translation>
    </message>
    <message>
        <source>The light already suits the analysis (%1 of %2 segments inside the window).</source>
        <translation>ライトはすでに解析結果に合っています（%2 セグメント中 %1 が範囲内）。</translation>
    </message>
    <message>
        <source>E&amp;xport…</source>
        <translation>エクスポート(&amp;X)…</translation>
    </message>
    <message numerus="yes">
        <source>Loaded %1: an animated base, %n frame(s) at %2 fps</source>
        <translation>
            <numerusform>%1 を読み込みました: アニメーションするベースモデル、%n フレーム、%2 fps</numerusform>
        </translation>
    </message>
    <message>
        <source>Import Key Deformation</source>
        <translation>キー変形をインポート</translation>
    </message>
    <message>
        <source>Show only the drawing&apos;s outline in the viewport, the one Fit to Drawing aims at (its threshold and closing radius are in the drawing&apos;s Properties), so the model&apos;s contours can be matched to it</source>
        <translation>ビューポートに参照画の輪郭だけを表示し、モデルの輪郭線を合わせられるようにします。これは「参照画に合わせる」が目標とする輪郭です（しきい値とクロージング半径は参照画の「プロパティ」で設定します）</translation>
    </message>
    <message>
        <source>Leave alignment and brush tools; a drawing not asked for with its eye is hidden</source>
        <translation>位置合わせとブラシのツールを終了します。目のアイコンで表示を指定していない参照画は隠れます</translation>
    </message>
    <message>
        <source>Show/Hide &amp;Drawing</source>
        <translation>参照画の表示/非表示(&amp;D)</translation>
    </message>
    <message>
        <source>Show the selected drawing over the model whatever is selected, or hide the drawing shown (the eye in the Scene panel)</source>
        <translation>選択に関係なく選択中の参照画をモデルの上に表示するか、表示中の参照画を隠します（シーンパネルの目のアイコン）</translation>
    </message>
    <message>
        <source>Export the animation seen through the camera path as glTF, a PC2 point cache, OBJ files or USD, as celform export does</source>
        <translation>カメラパスから見たアニメーションを glTF、PC2 ポイントキャッシュ、OBJ ファイル、USD として書き出します（celform export と同じ）</translation>
    </message>
    <message>
        <source>Optimise Light Along &amp;Shot</source>
        <translation>ショット全体でライトを最適化(&amp;S)</translation>
    </message>
    <message>
        <source>Optimise the light at every frame of the scene&apos;s range through the shot camera, each frame starting from the last, and key it there: a light track that turns no more than 3° a frame (one undo step)</source>
        <translation>シーンの範囲の各フレームでショットカメラを通してライトを最適化し、各フレームを前のフレームから始めてそこにキーします: 1 フレームあたり 3° 以上回転しないライトトラックです（1 回の取り消し単位）</translation>
    </message>
    <message>
        <source>Open a model first: the light is optimised for the pictures of a model.</source>
        <translation>まずモデルを開いてください: ライトはモデルの絵に対して最適化されます。</translation>
    </message>
    <message>
        <source>Light track optimisation cancelled: the light is unchanged.</source>
        <translation>ライトトラックの最適化をキャンセルしました: ライトは変わっていません。</translation>
    </message>
</context>
<context>
    <name>celform::app::OffsetActions</name>
    <message>
        <source>Automatic Shading Offsets</source>
        <translation>自動シェーディングオフセット</translation>
    </message>
    <message>
        <source>How far towards the solved offsets: 0 % changes nothing, 100 % gives every segment the wanted ratio (thesis figure 4.16).</source>
        <translation>求めたオフセットにどこまで近づけるか: 0 % では何も変わらず、100 % ではすべてのセグメントが目標の比率になります（論文の図 4.16）。</translation>
    </message>
    <message>
        <source>Fraction of each segment left dark: 0.5 puts the shading line through the middle of every segment.</source>
        <translation>各セグメントで暗部として残す割合: 0.5 ではすべてのセグメントの中央を陰影の境界線が通ります。</translation>
    </message>
    <message>
        <source>Rounds the offsets bleed to neighbouring vertices, so the edges between segments do not show (thesis figure 4.15).</source>
        <translation>オフセットを隣接頂点ににじませる回数。セグメント間の境目が目立たなくなります（論文の図 4.15）。</translation>
    </message>
    <message>
        <source>Base layer</source>
        <translation>ベースレイヤー</translation>
    </message>
    <message>
        <source>The layer that receives the offsets (the offset brush&apos;s target).</source>
        <translation>オフセットを書き込むレイヤー（オフセットブラシの対象）。</translation>
    </message>
    <message>
        <source>Aggressiveness:</source>
        <translation>適用度:</translation>
    </message>
    <message>
        <source>Percentile:</source>
        <translation>パーセンタイル:</translation>
    </message>
    <message>
        <source>Bleeding rounds:</source>
        <translation>にじみの回数:</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>対象:</translation>
    </message>
    <message>
        <source>Automatic shading offsets: %1 segments; depth error MSE %2 before, %3 after.</source>
        <translation>自動シェーディングオフセット: セグメント %1 個。奥行き誤差 MSE: 適用前 %2、適用後 %3。</translation>
    </message>
    <message>
        <source>Shading &amp;Offsets</source>
        <translation>シェーディングオフセット(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Paint Shading Offsets</source>
        <translation>シェーディングオフセットをペイント(&amp;P)</translation>
    </message>
    <message>
        <source>Offset brush: drag adds to N·L, Ctrl+drag subtracts, Shift+drag smooths (thesis 4.3)</source>
        <translation>オフセットブラシ: ドラッグで N·L に加算、Ctrl + ドラッグで減算、Shift + ドラッグで平滑化（論文 4.3）</translation>
    </message>
    <message>
        <source>Brush &amp;Mode</source>
        <translation>ブラシモード(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>加算(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Subtract</source>
        <translation>減算(&amp;S)</translation>
    </message>
    <message>
        <source>S&amp;mooth</source>
        <translation>平滑化(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Erase</source>
        <translation>消去(&amp;E)</translation>
    </message>
    <message>
        <source>What a plain drag of the offset brush does</source>
        <translation>オフセットブラシを修飾キーなしでドラッグしたときの動作</translation>
    </message>
    <message>
        <source>Brush S&amp;trength…</source>
        <translation>ブラシの強さ(&amp;T)…</translation>
    </message>
    <message>
        <source>The offset one dab adds at the brush&apos;s centre</source>
        <translation>1 回の打点でブラシの中心に加わるオフセット</translation>
    </message>
    <message>
        <source>Offset Brush Strength</source>
        <translation>オフセットブラシの強さ</translation>
    </message>
    <message>
        <source>Offset added at the centre by one dab:</source>
        <translation>1 回の打点で中心に加わるオフセット:</translation>
    </message>
    <message>
        <source>Paint into the Displayed &amp;Key&apos;s Layer</source>
        <translation>表示中のキーのレイヤーに描く(&amp;K)</translation>
    </message>
    <message>
        <source>On: the key shown in the viewport (Edit Key) at the playhead&apos;s frame; off: the base layer, every view and frame</source>
        <translation>オン: ビューポートに表示中のキー（「ブラシでキーを編集」）の現在のフレームに描きます。オフ: ベースレイヤー（すべての視点とフレーム）に描きます</translation>
    </message>
    <message>
        <source>No key is shown: choose Edit Key in the Scene panel first; painting the base layer.</source>
        <translation>表示中のキーがありません。先に「シーン」パネルで「ブラシでキーを編集」を選んでください。ベースレイヤーに描きます。</translation>
    </message>
    <message>
        <source>Shading offsets go into the %1.</source>
        <translation>シェーディングオフセットの書き込み先: %1。</translation>
    </message>
    <message>
        <source>&amp;Automatic Shading Offsets…</source>
        <translation>自動シェーディングオフセット(&amp;A)…</translation>
    </message>
    <message>
        <source>Give every segment of the depth analysis its shading line, seen from the current view (thesis 4.3)</source>
        <translation>現在の視点から見て、奥行き解析のすべてのセグメントに陰影の境界線が入るようにします（論文 4.3）</translation>
    </message>
    <message>
        <source>S&amp;mooth Shading Offsets</source>
        <translation>シェーディングオフセットを平滑化(&amp;M)</translation>
    </message>
    <message>
        <source>Four rounds of smoothing of the target layer over the mesh</source>
        <translation>対象レイヤーをメッシュ上で 4 回平滑化します</translation>
    </message>
    <message>
        <source>&amp;Clear Shading Offsets</source>
        <translation>シェーディングオフセットを消去(&amp;C)</translation>
    </message>
    <message>
        <source>Remove the target layer&apos;s offsets</source>
        <translation>対象レイヤーのオフセットを削除します</translation>
    </message>
    <message>
        <source>Analysing the picture (%1 × %2)…</source>
        <translation>画像を解析中（%1 × %2）…</translation>
    </message>
    <message>
        <source>Not enough memory to analyse %1 × %2 pixels</source>
        <translation>%1 × %2 ピクセルを解析するメモリが足りません</translation>
    </message>
    <message>
        <source>&amp;Mirror</source>
        <translation>ミラー(&amp;M)</translation>
    </message>
    <message>
        <source>Paint the mirror image across the project&apos;s mirror plane too (the brush&apos;s plane)</source>
        <translation>プロジェクトのミラー平面（ブラシの平面）をはさんだミラー像にも塗ります</translation>
    </message>
</context>
<context>
    <name>celform::app::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>環境設定</translation>
    </message>
    <message>
        <source>&amp;Navigation</source>
        <translation>ナビゲーション(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;General</source>
        <translation>一般(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Shortcuts</source>
        <translation>ショートカット(&amp;S)</translation>
    </message>
    <message>
        <source>Store and apply the preferences, keep the dialog open</source>
        <translation>設定を保存して適用します。ダイアログは開いたままです</translation>
    </message>
    <message>
        <source>Put every preference and key back to Celform&apos;s default (stored on OK or Apply)</source>
        <translation>すべての設定とキーを Celform の既定に戻します（OK か適用で保存されます）</translation>
    </message>
    <message>
        <source>Maya</source>
        <translation>Maya</translation>
    </message>
    <message>
        <source>Blender</source>
        <translation>Blender</translation>
    </message>
    <message>
        <source>Which mouse buttons and keys move the viewport&apos;s camera</source>
        <translation>ビューポートのカメラを動かすマウスボタンとキー</translation>
    </message>
    <message>
        <source>Navigation &amp;style:</source>
        <translation>ナビゲーション方式(&amp;S):</translation>
    </message>
    <message>
        <source>Turntable (around the up axis)</source>
        <translation>ターンテーブル（上方向の軸の周り）</translation>
    </message>
    <message>
        <source>Trackball (free, can roll over)</source>
        <translation>トラックボール（自由回転、裏返しも可）</translation>
    </message>
    <message>
        <source>Turntable keeps the model upright as Maya and Blender do by default; trackball turns freely about the view&apos;s axes</source>
        <translation>ターンテーブルは Maya や Blender の既定と同じくモデルを立てたまま回します。トラックボールは視点の軸の周りに自由に回します</translation>
    </message>
    <message>
        <source>&amp;Orbit:</source>
        <translation>回転(&amp;O):</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> 倍</translation>
    </message>
    <message>
        <source>How fast the camera turns for a drag: 1 is 0.4 degrees per pixel</source>
        <translation>ドラッグに対するカメラの回転の速さ: 1 で 1 ピクセルあたり 0.4 度</translation>
    </message>
    <message>
        <source>Orbit s&amp;peed:</source>
        <translation>回転の速さ(&amp;P):</translation>
    </message>
    <message>
        <source>Orbit around the point under the &amp;cursor</source>
        <translation>カーソル位置の点を中心に回転(&amp;C)</translation>
    </message>
    <message>
        <source>An orbit turns around the surface point where the drag starts (Maya&apos;s tumble pivot); elsewhere around the framed centre</source>
        <translation>ドラッグを始めた位置の面上の点を中心に回転します（Maya のタンブルピボット）。モデル外では表示範囲の中心の周りに回転します</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <source> min</source>
        <translation> 分</translation>
    </message>
    <message>
        <source>How often unsaved work is copied to a recovery file, offered after a crash; 0 turns autosave off</source>
        <translation>未保存の作業を復旧ファイルにコピーする間隔です（クラッシュ後に復旧を提案します）。0 で自動保存をオフにします</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>自動保存の間隔(&amp;A):</translation>
    </message>
    <message>
        <source>Unlimited</source>
        <translation>無制限</translation>
    </message>
    <message>
        <source>How many steps Undo can go back; older steps are forgotten</source>
        <translation>元に戻せるステップ数です。それより古いステップは破棄されます</translation>
    </message>
    <message>
        <source>&amp;Undo steps kept:</source>
        <translation>取り消し履歴の数(&amp;U):</translation>
    </message>
    <message>
        <source>System</source>
        <translation>システム</translation>
    </message>
    <message>
        <source>System (%1)</source>
        <translation>システム（%1）</translation>
    </message>
    <message>
        <source>The language of the editor&apos;s menus, panels and messages</source>
        <translation>エディターのメニュー、パネル、メッセージの言語</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>言語(&amp;L):</translation>
    </message>
    <message>
        <source>Toon</source>
        <translation>トゥーン</translation>
    </message>
    <message>
        <source>Gooch</source>
        <translation>Gooch</translation>
    </message>
    <message>
        <source>Comic</source>
        <translation>コミック</translation>
    </message>
    <message>
        <source>Lambert</source>
        <translation>ランバート</translation>
    </message>
    <message>
        <source>The shading style a project started from a mesh begins with (File ▸ New from Mesh); the rest of its look has Celform&apos;s defaults</source>
        <translation>メッシュから始めたプロジェクト（ファイル ▸ メッシュから新規作成）のシェーディング方式です。ルックのほかの設定は Celform の既定になります</translation>
    </message>
    <message>
        <source>New projects&apos; &amp;shading:</source>
        <translation>新規プロジェクトのシェーディング(&amp;S):</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>コマンド</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>ショートカット</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>既定</translation>
    </message>
    <message>
        <source>Filter by name, menu or key</source>
        <translation>名前、メニュー、キーで絞り込み</translation>
    </message>
    <message>
        <source>Click and press the new key for “%1”; the clear button removes it. Tab moves on.</source>
        <translation>クリックして「%1」の新しいキーを押してください。クリアボタンで削除します。Tab で次へ移動します。</translation>
    </message>
    <message>
        <source>&amp;Reset to Default</source>
        <translation>既定に戻す(&amp;R)</translation>
    </message>
    <message>
        <source>Give the selected command its default key again</source>
        <translation>選択したコマンドのキーを既定に戻します</translation>
    </message>
    <message>
        <source>Commands with several keys keep their other defaults (the view presets&apos; keypad keys, Redo&apos;s Ctrl+Y). The viewport&apos;s own keys are listed in Help ▸ Keyboard Shortcuts.</source>
        <translation>複数のキーを持つコマンドは、ほかの既定のキーを保ちます（視点プリセットのテンキー、やり直しの Ctrl+Y）。ビューポート固有のキーはヘルプ ▸ キーボードショートカットにあります。</translation>
    </message>
    <message>
        <source>Alt + left drag orbits, Alt + middle drag pans, Alt + right drag dollies; the middle button alone (with Shift: pan, Ctrl: dolly) and the wheel work too.</source>
        <translation>Alt + 左ドラッグで回転、Alt + 中ドラッグでパン、Alt + 右ドラッグでドリー。中ボタンのみ（Shift でパン、Ctrl でドリー）とホイールも使えます。</translation>
    </message>
    <message>
        <source>Middle drag orbits, Shift + middle drag pans, Ctrl + middle drag dollies, the wheel dollies; Alt + left drag goes to the tool.</source>
        <translation>中ドラッグで回転、Shift + 中ドラッグでパン、Ctrl + 中ドラッグとホイールでドリー。Alt + 左ドラッグはツールに渡ります。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Restart Celform to use the new language.&lt;/b&gt;</source>
        <translation>&lt;b&gt;新しい言語は Celform を再起動すると使われます。&lt;/b&gt;</translation>
    </message>
    <message>
        <source>A new language applies the next time Celform starts.</source>
        <translation>言語の変更は次に Celform を起動したときに反映されます。</translation>
    </message>
    <message>
        <source>The history holds steps now: the new limit applies when it is next empty (a project opened or started).</source>
        <translation>履歴にステップがあるため、新しい上限は履歴が次に空になったとき（プロジェクトを開くか新規作成したとき）に反映されます。</translation>
    </message>
    <message>
        <source>Fewer steps use less memory after long brushing sessions.</source>
        <translation>ステップ数を減らすと、長いブラシ作業の後のメモリ使用量が減ります。</translation>
    </message>
    <message>
        <source>Give each key to one command first</source>
        <translation>先に各キーを 1 つのコマンドだけに割り当ててください</translation>
    </message>
    <message>
        <source>Your desktop (%1) may take Alt + drag to move windows: if the viewport does not orbit, choose Blender, which needs no Alt.</source>
        <translation>お使いのデスクトップ（%1）は Alt + ドラッグをウィンドウの移動に使うことがあります: ビューポートが回転しない場合は、Alt を使わない Blender を選んでください。</translation>
    </message>
</context>
<context>
    <name>celform::app::ProgressDialog</name>
    <message>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
</context>
<context>
    <name>celform::app::RenderDialog</name>
    <message>
        <source>Render Image</source>
        <translation>画像をレンダー</translation>
    </message>
    <message>
        <source>Render Sequence</source>
        <translation>連番をレンダー</translation>
    </message>
    <message>
        <source>The image to write: .png, .tif or .jpg (8-bit sRGB) or .exr (linear float; every pass as channels unless a pass is chosen)</source>
        <translation>書き出す画像: .png、.tif、.jpg（8 ビット sRGB）または .exr（リニア浮動小数点。パスを選ばなければ全パスをチャンネルとして保存）</translation>
    </message>
    <message>
        <source>The frames to write: a run of # becomes the zero-padded frame number (shot_####.png); without one, _0001 and so on go before the suffix</source>
        <translation>書き出すフレーム: 連続した # はゼロ埋めのフレーム番号になります（shot_####.png）。# がなければ拡張子の前に _0001 などが付きます</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <source>Choose the output file and its format</source>
        <translation>出力ファイルと形式を選びます</translation>
    </message>
    <message>
        <source>&amp;Output file:</source>
        <translation>出力ファイル(&amp;O):</translation>
    </message>
    <message>
        <source>&amp;Output files:</source>
        <translation>出力ファイル(&amp;O):</translation>
    </message>
    <message>
        <source>The camera the render looks through; the shape is the view-dependent blend for it</source>
        <translation>レンダーに使うカメラです。形状はこのカメラに対する視点依存ブレンドになります</translation>
    </message>
    <message>
        <source>&amp;Camera:</source>
        <translation>カメラ(&amp;C):</translation>
    </message>
    <message>
        <source>The frame to render: the animated base model, the keys&apos; deformations and the highlights at it</source>
        <translation>レンダーするフレーム: そのフレームでのアニメーションするベースモデル、キー変形、ハイライト</translation>
    </message>
    <message>
        <source>&amp;Frame:</source>
        <translation>フレーム(&amp;F):</translation>
    </message>
    <message>
        <source>The first frame of the sequence</source>
        <translation>連番の最初のフレーム</translation>
    </message>
    <message>
        <source>The last frame of the sequence (included)</source>
        <translation>連番の最後のフレーム（含む）</translation>
    </message>
    <message>
        <source>to</source>
        <translation>～</translation>
    </message>
    <message>
        <source>&amp;Frames:</source>
        <translation>フレーム(&amp;F):</translation>
    </message>
    <message>
        <source>Common image sizes; editing the width or height makes it a custom size</source>
        <translation>よく使う画像サイズです。幅か高さを変えるとカスタムになります</translation>
    </message>
    <message>
        <source>HD 720p</source>
        <translation>HD 720p</translation>
    </message>
    <message>
        <source>Full HD 1080p</source>
        <translation>フル HD 1080p</translation>
    </message>
    <message>
        <source>UHD 4K</source>
        <translation>UHD 4K</translation>
    </message>
    <message>
        <source>2K scope (2.39:1)</source>
        <translation>2K スコープ（2.39:1）</translation>
    </message>
    <message>
        <source>Square 1024</source>
        <translation>正方形 1024</translation>
    </message>
    <message>
        <source>%1 (%2 × %3)</source>
        <translation>%1（%2 × %3）</translation>
    </message>
    <message>
        <source>Viewport (%1 × %2)</source>
        <translation>ビューポート（%1 × %2）</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>カスタム</translation>
    </message>
    <message>
        <source>Si&amp;ze:</source>
        <translation>サイズ(&amp;Z):</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Image width in pixels (at most 16384)</source>
        <translation>画像の幅（ピクセル、最大 16384）</translation>
    </message>
    <message>
        <source>Image height in pixels (at most 16384)</source>
        <translation>画像の高さ（ピクセル、最大 16384）</translation>
    </message>
    <message>
        <source>&amp;Width × height:</source>
        <translation>幅 × 高さ(&amp;W):</translation>
    </message>
    <message>
        <source>What to write: the finished picture (beauty) or one of the renderer&apos;s passes; an .exr can hold every pass as named channels</source>
        <translation>書き出す内容: 完成画像（ビューティー）またはレンダラーのパスの 1 つ。.exr には全パスを名前付きチャンネルとして保存できます</translation>
    </message>
    <message>
        <source>Beauty (the finished picture)</source>
        <translation>ビューティー（完成画像）</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>線</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>階調</translation>
    </message>
    <message>
        <source>Highlights</source>
        <translation>ハイライト</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>深度</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>法線</translation>
    </message>
    <message>
        <source>Object ids</source>
        <translation>オブジェクト ID</translation>
    </message>
    <message>
        <source>All passes (EXR channels)</source>
        <translation>全パス（EXR チャンネル）</translation>
    </message>
    <message>
        <source>&amp;Pass:</source>
        <translation>パス(&amp;P):</translation>
    </message>
    <message>
        <source>Render both eyes and compose them (the look&apos;s stereo settings); a stereo render writes the beauty pass</source>
        <translation>両眼をレンダーして合成します（ルックのステレオ設定）。ステレオではビューティーパスを書き出します</translation>
    </message>
    <message>
        <source>Off (mono)</source>
        <translation>オフ（モノ）</translation>
    </message>
    <message>
        <source>Anaglyph</source>
        <translation>アナグリフ</translation>
    </message>
    <message>
        <source>Dubois anaglyph</source>
        <translation>Dubois アナグリフ</translation>
    </message>
    <message>
        <source>Half-colour anaglyph</source>
        <translation>ハーフカラーアナグリフ</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>サイドバイサイド</translation>
    </message>
    <message>
        <source>Top-bottom</source>
        <translation>トップアンドボトム</translation>
    </message>
    <message>
        <source>&amp;Stereo:</source>
        <translation>ステレオ(&amp;S):</translation>
    </message>
    <message>
        <source>Shade this render in another style; the project&apos;s look is not changed</source>
        <translation>このレンダーだけ別の方式でシェーディングします。プロジェクトのルックは変わりません</translation>
    </message>
    <message>
        <source>As in the project</source>
        <translation>プロジェクトの設定どおり</translation>
    </message>
    <message>
        <source>Toon</source>
        <translation>トゥーン</translation>
    </message>
    <message>
        <source>Gooch</source>
        <translation>Gooch</translation>
    </message>
    <message>
        <source>Comic</source>
        <translation>コミック</translation>
    </message>
    <message>
        <source>Lambert</source>
        <translation>ランバート</translation>
    </message>
    <message>
        <source>St&amp;yle:</source>
        <translation>スタイル(&amp;Y):</translation>
    </message>
    <message>
        <source>Draw the lines or not in this render; the project&apos;s look is not changed</source>
        <translation>このレンダーで線を描くかどうか。プロジェクトのルックは変わりません</translation>
    </message>
    <message>
        <source>On</source>
        <translation>オン</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <source>&amp;Lines:</source>
        <translation>線(&amp;L):</translation>
    </message>
    <message>
        <source>Open the image when done</source>
        <translation>完了したら画像を開く</translation>
    </message>
    <message>
        <source>Open the folder when done</source>
        <translation>完了したらフォルダーを開く</translation>
    </message>
    <message>
        <source>Show the result in the desktop&apos;s image viewer or file manager</source>
        <translation>結果をデスクトップの画像ビューアーかファイルマネージャーで表示します</translation>
    </message>
    <message>
        <source>&amp;Render</source>
        <translation>レンダー(&amp;R)</translation>
    </message>
    <message>
        <source>Render with these options; Cancel in the progress window stops between frames</source>
        <translation>この設定でレンダーします。進行状況ウィンドウのキャンセルでフレームの間で止まります</translation>
    </message>
    <message>
        <source>Render camera (the project&apos;s)</source>
        <translation>レンダーカメラ（プロジェクト）</translation>
    </message>
    <message>
        <source>Current view</source>
        <translation>現在の視点</translation>
    </message>
    <message>
        <source>Framed default view</source>
        <translation>既定の視点（全体表示）</translation>
    </message>
    <message>
        <source>Key: %1</source>
        <translation>キー: %1</translation>
    </message>
    <message>
        <source>Drawing: %1</source>
        <translation>参照画: %1</translation>
    </message>
    <message>
        <source>render</source>
        <translation>render</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 画像 (*.png)</translation>
    </message>
    <message>
        <source>OpenEXR images (*.exr)</source>
        <translation>OpenEXR 画像 (*.exr)</translation>
    </message>
    <message>
        <source>TIFF images (*.tif *.tiff)</source>
        <translation>TIFF 画像 (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>JPEG images (*.jpg *.jpeg)</source>
        <translation>JPEG 画像 (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <source>The project has no base model to render.</source>
        <translation>プロジェクトにレンダーするベースモデルがありません。</translation>
    </message>
    <message>
        <source>Choose the output file.</source>
        <translation>出力ファイルを選んでください。</translation>
    </message>
    <message>
        <source>%1: the folder does not exist.</source>
        <translation>%1: フォルダーがありません。</translation>
    </message>
    <message>
        <source>%1 is a folder: give a file name.</source>
        <translation>%1 はフォルダーです。ファイル名を指定してください。</translation>
    </message>
    <message>
        <source>The last frame comes before the first.</source>
        <translation>最後のフレームが最初のフレームより前です。</translation>
    </message>
    <message>
        <source>At most %L1 frames can be rendered at a time.</source>
        <translation>一度にレンダーできるのは %L1 フレームまでです。</translation>
    </message>
    <message>
        <source>%1 × %2 is more than 8192 × 8192 pixels, the most the renderer takes.</source>
        <translation>%1 × %2 はレンダラーの上限 8192 × 8192 ピクセルを超えています。</translation>
    </message>
    <message>
        <source>%1 × %2 needs about %3 GB of memory to render, and %4 GB are available.</source>
        <translation>%1 × %2 のレンダーには約 %3 GB のメモリが必要ですが、使えるのは %4 GB です。</translation>
    </message>
    <message>
        <source>Writes %1 … %2 (%L3 frames)</source>
        <translation>%1 … %2 を書き出します（%L3 フレーム）</translation>
    </message>
    <message>
        <source>Writes %1</source>
        <translation>%1 を書き出します</translation>
    </message>
    <message>
        <source>%L1 of the %L2 files already exist. Replace them?</source>
        <translation>%L2 個のファイルのうち %L1 個がすでにあります。置き換えますか？</translation>
    </message>
    <message>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 はすでにあります。置き換えますか？</translation>
    </message>
    <message>
        <source>Shot camera (the camera path)</source>
        <translation>ショットカメラ（カメラパス）</translation>
    </message>
    <message>
        <source>Tone regions in the SVG</source>
        <translation>SVG にトーン領域を含める</translation>
    </message>
    <message>
        <source>With an .svg output: the tone regions as filled layers under the strokes, for editing in Inkscape or Illustrator</source>
        <translation>.svg 出力で: トーン領域をストロークの下に塗りつぶしレイヤーとして書き出します（Inkscape や Illustrator での編集用）</translation>
    </message>
    <message>
        <source>SVG vector lines (*.svg)</source>
        <translation>SVG ベクター線画 (*.svg)</translation>
    </message>
    <message>
        <source>%1: the output must end in .png, .exr, .tif, .jpg or .svg.</source>
        <translation>%1: 出力ファイルの拡張子は .png、.exr、.tif、.jpg、.svg のいずれかにしてください。</translation>
    </message>
    <message>
        <source>An SVG holds one group of strokes per eye: choose mono, anaglyph, side by side or top-bottom.</source>
        <translation>SVG には左右の目ごとにストロークのグループが 1 つずつ入ります: モノ、アナグリフ、サイドバイサイド、トップアンドボトムのいずれかを選んでください。</translation>
    </message>
</context>
<context>
    <name>celform::app::RenderRunner</name>
    <message>
        <source>Render Sequence</source>
        <translation>連番をレンダー</translation>
    </message>
    <message>
        <source>Render Image</source>
        <translation>画像をレンダー</translation>
    </message>
    <message>
        <source>Rendering frame %1 (1 of %2)…</source>
        <translation>フレーム %1 をレンダー中（1 / %2）…</translation>
    </message>
    <message>
        <source>Rendering %1 (%2 × %3)…</source>
        <translation>%1 をレンダー中（%2 × %3）…</translation>
    </message>
    <message>
        <source>%1: not enough memory to render %2 × %3 pixels</source>
        <translation>%1: %2 × %3 ピクセルをレンダーするメモリが足りません</translation>
    </message>
    <message>
        <source>Stopping the render after the frame being drawn…</source>
        <translation>描画中のフレームの後でレンダーを止めています…</translation>
    </message>
    <message>
        <source>Rendering frame %1 (%2 of %3)…</source>
        <translation>フレーム %1 をレンダー中（%2 / %3）…</translation>
    </message>
    <message>
        <source>Render Failed</source>
        <translation>レンダーに失敗しました</translation>
    </message>
    <message>
        <source>The render could not be finished.</source>
        <translation>レンダーを完了できませんでした。</translation>
    </message>
    <message>
        <source>The frames written before the error are kept (%L1).</source>
        <translation>エラーの前に書き出したフレームは残してあります（%L1）。</translation>
    </message>
    <message>
        <source>Render failed: %1</source>
        <translation>レンダーに失敗しました: %1</translation>
    </message>
    <message>
        <source>Render cancelled; the files written are kept (%L1).</source>
        <translation>レンダーをキャンセルしました。書き出したファイルは残してあります（%L1）。</translation>
    </message>
    <message>
        <source>Rendered %L1 frames to %2</source>
        <translation>%L1 フレームを %2 にレンダーしました</translation>
    </message>
    <message>
        <source>Rendered %1</source>
        <translation>%1 をレンダーしました</translation>
    </message>
    <message>
        <source>Render Finished</source>
        <translation>レンダー完了</translation>
    </message>
    <message>
        <source>No file manager could be opened. The frames are in:</source>
        <translation>ファイルマネージャーを開けませんでした。フレームの保存先:</translation>
    </message>
    <message>
        <source>No image viewer could be opened. The image is:</source>
        <translation>画像ビューアーを開けませんでした。画像の保存先:</translation>
    </message>
</context>
<context>
    <name>celform::app::ReviewWindow</name>
    <message>
        <source>Stereo Review</source>
        <translation>ステレオレビュー</translation>
    </message>
    <message>
        <source>Anaglyph</source>
        <translation>アナグリフ</translation>
    </message>
    <message>
        <source>Dubois anaglyph</source>
        <translation>Dubois アナグリフ</translation>
    </message>
    <message>
        <source>Half-colour anaglyph</source>
        <translation>ハーフカラーアナグリフ</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>サイドバイサイド</translation>
    </message>
    <message>
        <source>Top-bottom</source>
        <translation>トップアンドボトム</translation>
    </message>
    <message>
        <source>Mono</source>
        <translation>モノ（単眼）</translation>
    </message>
    <message>
        <source>free camera</source>
        <translation>フリーカメラ</translation>
    </message>
    <message>
        <source>Key: %1</source>
        <translation>キー: %1</translation>
    </message>
    <message>
        <source>Interocular %1</source>
        <translation>眼間距離 %1</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 fps</translation>
    </message>
    <message>
        <source>Turntable</source>
        <translation>ターンテーブル</translation>
    </message>
    <message>
        <source>No lines</source>
        <translation>線なし</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>プレビュー</translation>
    </message>
    <message>
        <source>H: help</source>
        <translation>H: ヘルプ</translation>
    </message>
    <message>
        <source>Idle (last frame %1 ms)</source>
        <translation>待機中（直前のフレーム %1 ms）</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stereo review&lt;/b&gt;</source>
        <translation>&lt;b&gt;ステレオレビュー&lt;/b&gt;</translation>
    </message>
    <message>
        <source>turntable on / off</source>
        <translation>ターンテーブルのオン / オフ</translation>
    </message>
    <message>
        <source>previous key&apos;s camera</source>
        <translation>前のキーのカメラ</translation>
    </message>
    <message>
        <source>next key&apos;s camera</source>
        <translation>次のキーのカメラ</translation>
    </message>
    <message>
        <source>stereo: anaglyph, Dubois, half-colour, side by side, top-bottom, off</source>
        <translation>ステレオ: アナグリフ、Dubois、ハーフカラー、サイドバイサイド、トップアンドボトム、オフ</translation>
    </message>
    <message>
        <source>lines on / off</source>
        <translation>線のオン / オフ</translation>
    </message>
    <message>
        <source>view-dependent preview on / off</source>
        <translation>視点依存プレビューのオン / オフ</translation>
    </message>
    <message>
        <source>interocular distance -10%</source>
        <translation>眼間距離 -10%</translation>
    </message>
    <message>
        <source>interocular distance +10%</source>
        <translation>眼間距離 +10%</translation>
    </message>
    <message>
        <source>this help</source>
        <translation>このヘルプ</translation>
    </message>
    <message>
        <source>close the review</source>
        <translation>レビューを閉じる</translation>
    </message>
</context>
<context>
    <name>celform::app::ShortcutList</name>
    <message>
        <source>&amp;Filter:</source>
        <translation>絞り込み(&amp;F):</translation>
    </message>
    <message>
        <source>No command matches “%1”.</source>
        <translation>「%1」に一致するコマンドはありません。</translation>
    </message>
</context>
<context>
    <name>celform::app::Shortcuts</name>
    <message>
        <source>Other</source>
        <translation>その他</translation>
    </message>
    <message>
        <source>Viewport</source>
        <translation>ビューポート</translation>
    </message>
    <message>
        <source>Viewport ▸ Brush tool</source>
        <translation>ビューポート ▸ ブラシツール</translation>
    </message>
    <message>
        <source>Stereo Review</source>
        <translation>ステレオレビュー</translation>
    </message>
    <message>
        <source>%1 is given to “%2” and to %3.</source>
        <translation>%1 が「%2」と %3 の両方に割り当てられています。</translation>
    </message>
    <message>
        <source> and </source>
        <comment>between action names</comment>
        <translation>、</translation>
    </message>
    <message>
        <source>%1 is the viewport&apos;s key for “%2”: “%3” takes it first.</source>
        <translation>%1 はビューポートの「%2」のキーです。「%3」が先に受け取ります。</translation>
    </message>
</context>
<context>
    <name>celform::app::ShortcutsDialog</name>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>キーボードショートカット</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>コマンド</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <translation>ショートカット</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <source>Filter by name, menu or key (save, view, ctrl+s)</source>
        <translation>名前、メニュー、キーで絞り込み（保存、表示、ctrl+s）</translation>
    </message>
    <message>
        <source>Shows the shortcuts whose name, menu, key or description contains the text</source>
        <translation>名前、メニュー、キー、説明にこの文字列を含むショートカットを表示します</translation>
    </message>
    <message>
        <source>Change the keys in Edit ▸ Preferences ▸ Shortcuts</source>
        <translation>キーは 編集 ▸ 環境設定 ▸ ショートカット で変更できます</translation>
    </message>
    <message>
        <source>Keys of menu commands can be changed in Edit ▸ Preferences ▸ Shortcuts. The viewport&apos;s and the stereo review&apos;s own keys are fixed; Help ▸ Navigation shows the mouse.</source>
        <translation>メニューコマンドのキーは 編集 ▸ 環境設定 ▸ ショートカット で変更できます。ビューポートとステレオレビュー固有のキーは固定です。マウス操作はヘルプ ▸ ナビゲーションにあります。</translation>
    </message>
</context>
<context>
    <name>celform::app::SubdivisionActions</name>
    <message>
        <source>Control mesh shown (3: smooth surface, level %1)</source>
        <translation>コントロールメッシュを表示中（3: 滑らかな面、レベル %1）</translation>
    </message>
    <message>
        <source>Viewport subdivision capped at level %1 of %2: %3 triangles</source>
        <translation>ビューポートの細分割をレベル %2 中 %1 に制限: %3 三角形</translation>
    </message>
    <message>
        <source>Viewport subdivision level %1 (renders use level %2)</source>
        <translation>ビューポートの細分割レベル %1（レンダリングはレベル %2）</translation>
    </message>
    <message>
        <source>The subdivision level the viewport shows (Look dock, Smooth surface)</source>
        <translation>ビューポートが表示する細分割レベル（ルックドック、滑らかな面）</translation>
    </message>
    <message>
        <source>Control &amp;Mesh</source>
        <translation>コントロールメッシュ(&amp;M)</translation>
    </message>
    <message>
        <source>Show the control mesh in the viewport, without subdivision (as Maya&apos;s 1)</source>
        <translation>細分割なしでコントロールメッシュをビューポートに表示します（Maya の 1 と同じ）</translation>
    </message>
    <message>
        <source>&amp;Smooth Surface</source>
        <translation>滑らかな面(&amp;S)</translation>
    </message>
    <message>
        <source>Show the subdivided surface at the look&apos;s viewport level, as renders show it (as Maya&apos;s 3)</source>
        <translation>ルックのビューポートレベルで細分割された面を、レンダリングと同じように表示します（Maya の 3 と同じ）</translation>
    </message>
    <message>
        <source>Show Control &amp;Cage</source>
        <translation>コントロールケージを表示(&amp;C)</translation>
    </message>
    <message>
        <source>Draw the control mesh as a wireframe over the smooth surface</source>
        <translation>コントロールメッシュを滑らかな面の上にワイヤーフレームで描きます</translation>
    </message>
</context>
<context>
    <name>celform::app::TurntableDialog</name>
    <message>
        <source>Turntable</source>
        <translation>ターンテーブル</translation>
    </message>
    <message>
        <source>Frames of one revolution; the scene&apos;s range becomes these frames</source>
        <translation>1 周のフレーム数。シーンの範囲はこのフレームになります</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y (up)</source>
        <translation>Y（上）</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>The axis the camera turns around, through the model&apos;s centre</source>
        <translation>カメラが回る軸（モデルの中心を通ります）</translation>
    </message>
    <message>
        <source>How far the camera is raised above the plane normal to the axis</source>
        <translation>軸に垂直な平面からカメラを持ち上げる高さ</translation>
    </message>
    <message>
        <source>The frame the revolution starts at</source>
        <translation>回転を始めるフレーム</translation>
    </message>
    <message>
        <source>Where on the circle the camera starts: 0 is the side the default view looks from</source>
        <translation>円周上のカメラの開始位置: 0 は既定の視点が見ている側です</translation>
    </message>
    <message>
        <source>Frames per revolution:</source>
        <translation>1 周のフレーム数:</translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <source>Elevation:</source>
        <translation>仰角:</translation>
    </message>
    <message>
        <source>Start frame:</source>
        <translation>開始フレーム:</translation>
    </message>
    <message>
        <source>Start angle:</source>
        <translation>開始角度:</translation>
    </message>
    <message>
        <source>Replace the camera path by the turntable (one undo step)</source>
        <translation>カメラパスをターンテーブルで置き換えます（1 回の「元に戻す」で戻せます）</translation>
    </message>
</context>
<context>
    <name>celform::model</name>
    <message>
        <source>base</source>
        <translation>ベース</translation>
    </message>
    <message>
        <source>Shading offsets need a base model.</source>
        <translation>シェーディングオフセットにはベースモデルが必要です。</translation>
    </message>
    <message>
        <source>There is no key to hold the automatic shading offsets.</source>
        <translation>自動シェーディングオフセットを保持するキーがありません。</translation>
    </message>
    <message>
        <source>The aggressiveness must be between 0 and 1.</source>
        <translation>適用度は 0～1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>The percentile must be between 0 and 1.</source>
        <translation>パーセンタイルは 0～1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>Bleeding takes 0 to %1 rounds.</source>
        <translation>にじみの回数は 0～%1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>The analysis size must be between 16 and 8192 pixels a side.</source>
        <translation>解析サイズは一辺 16～8192 ピクセルの範囲で指定してください。</translation>
    </message>
    <message>
        <source>The analysis needs a valid camera (eye, target and up must differ).</source>
        <translation>解析には有効なカメラが必要です（カメラ位置、注視点、上方向はそれぞれ異なる必要があります）。</translation>
    </message>
    <message>
        <source>The key “%1” plays no part in this view: look from nearer its direction.</source>
        <translation>キー「%1」はこの視点では使われていません。キーの方向にもっと近い視点から見てください。</translation>
    </message>
    <message>
        <source>The automatic shading offsets could not be solved for this picture.</source>
        <translation>この画像では自動シェーディングオフセットを求められませんでした。</translation>
    </message>
    <message>
        <source>Shading offsets refused: %1.</source>
        <translation>シェーディングオフセットを適用できません: %1。</translation>
    </message>
    <message>
        <source>The drawing “%1” has no image to read an outline from.</source>
        <translation>参照画「%1」には輪郭を読み取る画像がありません。</translation>
    </message>
    <message>
        <source>The drawing “%1” is all one tone: no figure stands out from the paper. Set the outline threshold by hand.</source>
        <translation>参照画「%1」は全体が同じ濃さで、紙から浮かび上がる図形がありません。輪郭のしきい値を手動で設定してください。</translation>
    </message>
    <message>
        <source>The drawing “%1” has no closed outline: its lines never enclose the figure. Raise the closing radius to bridge the gaps.</source>
        <translation>参照画「%1」には閉じた輪郭がありません。線が図形を囲んでいません。クロージング半径を大きくしてすき間をつないでください。</translation>
    </message>
    <message>
        <source>The figure in the drawing “%1” touches the image border, so its outline is cut off by the frame. Use a drawing with paper around the character.</source>
        <translation>参照画「%1」の図形が画像の端に接しているため、輪郭が画像の枠で切れています。キャラクターの周りに余白のある参照画を使ってください。</translation>
    </message>
    <message>
        <source>The key “%1” is not linked to a drawing. Link it to the drawing to fit first.</source>
        <translation>キー「%1」は参照画にリンクされていません。先に、合わせる参照画にリンクしてください。</translation>
    </message>
    <message>
        <source>The drawing to fit no longer exists.</source>
        <translation>合わせる参照画はすでに存在しません。</translation>
    </message>
    <message>
        <source>The key “%1” is not linked to the drawing “%2”.</source>
        <translation>キー「%1」は参照画「%2」にリンクされていません。</translation>
    </message>
    <message>
        <source>Fit Camera to Drawing needs a base model and a drawing.</source>
        <translation>「カメラを参照画に合わせる」にはベースモデルと参照画が必要です。</translation>
    </message>
    <message>
        <source>The camera could not be fitted to the drawing “%1”: %2</source>
        <translation>カメラを参照画「%1」に合わせられませんでした: %2</translation>
    </message>
    <message>
        <source>Fit Shape to Drawing needs a base model and a key.</source>
        <translation>「形状を参照画に合わせる」にはベースモデルとキーが必要です。</translation>
    </message>
    <message>
        <source>There is no painted face set “%1” to fit within.</source>
        <translation>合わせる範囲となるペイント済みの面セット「%1」がありません。</translation>
    </message>
    <message>
        <source>There is no painted face set “%1” to pin.</source>
        <translation>ピン留めするペイント済みの面セット「%1」がありません。</translation>
    </message>
    <message>
        <source>The strength of a fit must lie in 0 to 1.</source>
        <translation>合わせ込みの強さは 0～1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>The key “%1” could not be fitted to the drawing “%2”: %3</source>
        <translation>キー「%1」を参照画「%2」に合わせられませんでした: %3</translation>
    </message>
    <message>
        <source>There is no segment %1 in this picture (it has %2).</source>
        <translation>この画像にはセグメント %1 がありません（セグメント数は %2 です）。</translation>
    </message>
    <message>
        <source>A merge needs two different segments.</source>
        <translation>結合には異なる 2 つのセグメントが必要です。</translation>
    </message>
    <message>
        <source>A split needs a stroke of at least two points.</source>
        <translation>分割には 2 点以上のストロークが必要です。</translation>
    </message>
    <message>
        <source>The stroke does not cross segment %1: its faces all lie on one side.</source>
        <translation>ストロークがセグメント %1 を横切っていません: その面はすべて片側にあります。</translation>
    </message>
</context>
<context>
    <name>celform::model::AnimationEdits</name>
    <message>
        <source>Change Frame Rate</source>
        <translation>フレームレートを変更</translation>
    </message>
    <message>
        <source>Change Frame Range</source>
        <translation>フレーム範囲を変更</translation>
    </message>
    <message>
        <source>The camera is not valid (eye, target and up must differ).</source>
        <translation>カメラが無効です（カメラ位置、注視点、上方向はそれぞれ異なる必要があります）。</translation>
    </message>
    <message>
        <source>Frame %1 is out of range.</source>
        <translation>フレーム %1 は範囲外です。</translation>
    </message>
    <message>
        <source>Key Camera at Frame %1</source>
        <translation>フレーム %1 にカメラのキーフレームを設定</translation>
    </message>
    <message>
        <source>Remove Camera Key at Frame %1</source>
        <translation>フレーム %1 のカメラのキーフレームを削除</translation>
    </message>
    <message>
        <source>Clear Camera Path</source>
        <translation>カメラパスを消去</translation>
    </message>
    <message>
        <source>Import a base model before making a turntable.</source>
        <translation>ターンテーブルを作成する前にベースモデルをインポートしてください。</translation>
    </message>
    <message>
        <source>Make Turntable</source>
        <translation>ターンテーブルを作成</translation>
    </message>
    <message>
        <source>The animation of %1 is not usable: %2</source>
        <translation>%1 のアニメーションを使用できません: %2</translation>
    </message>
    <message>
        <source>has %1 vertices, but the key deformations use vertex %2; a replacement base model needs the same vertex count and order</source>
        <translation>頂点数が %1 ですが、キー変形では頂点 %2 が使われています。置き換えるベースモデルは頂点数と頂点順序が同じである必要があります</translation>
    </message>
    <message>
        <source>Import Animated Base</source>
        <translation>アニメーションするベースモデルをインポート</translation>
    </message>
</context>
<context>
    <name>celform::model::AnimationIo</name>
    <message>
        <source>%1 frames per second is not a usable frame rate</source>
        <translation>%1 fps は使用できるフレームレートではありません</translation>
    </message>
    <message>
        <source>the file contains no triangles</source>
        <translation>ファイルに三角形がありません</translation>
    </message>
    <message>
        <source>the animation is unusable: %1</source>
        <translation>アニメーションを使用できません: %1</translation>
    </message>
    <message>
        <source>mesh %1, primitive %2</source>
        <translation>メッシュ %1、プリミティブ %2</translation>
    </message>
    <message>
        <source>the scene names node %1, which does not exist</source>
        <translation>シーンが存在しないノード %1 を参照しています</translation>
    </message>
    <message>
        <source>the scene reaches node %1 twice</source>
        <translation>シーンからノード %1 に 2 回到達します</translation>
    </message>
    <message>
        <source>%1 has %2 morph targets, the mesh&apos;s first primitive %3</source>
        <translation>%1 のモーフターゲットは %2 個ですが、メッシュの最初のプリミティブでは %3 個です</translation>
    </message>
    <message>
        <source>mesh %1 has %2 morph targets</source>
        <translation>メッシュ %1 にはモーフターゲットが %2 個あります</translation>
    </message>
    <message>
        <source>%1 has only one of JOINTS_%2 and WEIGHTS_%2</source>
        <translation>%1 には JOINTS_%2 と WEIGHTS_%2 の片方しかありません</translation>
    </message>
    <message>
        <source>%1: JOINTS_%2 and WEIGHTS_%2 give %3 and %4 vertices, POSITION %5</source>
        <translation>%1: JOINTS_%2 と WEIGHTS_%2 の頂点数は %3 と %4 ですが、POSITION では %5 です</translation>
    </message>
    <message>
        <source>%1 is skinned but has no JOINTS_0 and WEIGHTS_0</source>
        <translation>%1 はスキンが設定されていますが、JOINTS_0 と WEIGHTS_0 がありません</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a joint weight that is negative or not a number</source>
        <translation>%1: 頂点 %2 のジョイントウェイトが負の値か数値ではありません</translation>
    </message>
    <message>
        <source>%1: vertex %2 names joint %3, but the skin has %4 joints</source>
        <translation>%1: 頂点 %2 がジョイント %3 を参照していますが、スキンのジョイントは %4 個です</translation>
    </message>
    <message>
        <source>skin %1 has no joints</source>
        <translation>スキン %1 にジョイントがありません</translation>
    </message>
    <message>
        <source>skin %1</source>
        <translation>スキン %1</translation>
    </message>
    <message>
        <source>skin %1 has %2 inverse bind matrices for %3 joints</source>
        <translation>スキン %1 には %3 個のジョイントに対して逆バインド行列が %2 個あります</translation>
    </message>
    <message>
        <source>skin %1 names node %2, which does not exist</source>
        <translation>スキン %1 が存在しないノード %2 を参照しています</translation>
    </message>
    <message>
        <source>skin %1: joint %2&apos;s inverse bind matrix is not finite</source>
        <translation>スキン %1: ジョイント %2 の逆バインド行列が有限ではありません</translation>
    </message>
    <message>
        <source>node %1 names mesh %2, which does not exist</source>
        <translation>ノード %1 が存在しないメッシュ %2 を参照しています</translation>
    </message>
    <message>
        <source>node %1 names skin %2, which does not exist</source>
        <translation>ノード %1 が存在しないスキン %2 を参照しています</translation>
    </message>
    <message>
        <source>the scene has more morph targets than Celform can hold</source>
        <translation>シーンのモーフターゲットが Celform で扱える上限を超えています</translation>
    </message>
    <message>
        <source>node %1 gives %2 morph weights for the %3 morph targets of mesh %4</source>
        <translation>ノード %1 にはメッシュ %4 の %3 個のモーフターゲットに対してモーフウェイトが %2 個あります</translation>
    </message>
    <message>
        <source>the scene has no mesh</source>
        <translation>シーンにメッシュがありません</translation>
    </message>
    <message>
        <source>node %1 is animated but has a zero scale at rest</source>
        <translation>ノード %1 はアニメーションしますが、静止時のスケールがゼロです</translation>
    </message>
    <message>
        <source>the file has more than 65,535 joints</source>
        <translation>ファイルのジョイントが 65,535 個を超えています</translation>
    </message>
    <message>
        <source>%1 has the unknown mode %2</source>
        <translation>%1 のモード %2 は不明です</translation>
    </message>
    <message>
        <source>%1 has no POSITION</source>
        <translation>%1 に POSITION がありません</translation>
    </message>
    <message>
        <source>the scene has more than the %1 vertices Celform can load</source>
        <translation>シーンの頂点が、Celform が読み込める %1 個を超えています</translation>
    </message>
    <message>
        <source>%1: index %2 is %3, but the primitive has %4 vertices</source>
        <translation>%1: インデックス %2 は %3 ですが、プリミティブの頂点数は %4 です</translation>
    </message>
    <message>
        <source>%1: vertex %2 has a coordinate that is not a finite number</source>
        <translation>%1: 頂点 %2 の座標に有限の数値でないものがあります</translation>
    </message>
    <message>
        <source>%1: vertex %2 is beyond the range of a float once its node&apos;s transform is applied</source>
        <translation>%1: 頂点 %2 はノードの変換を適用すると float の範囲を超えます</translation>
    </message>
    <message>
        <source>the scene has more than the %1 triangles Celform can load</source>
        <translation>シーンの三角形が、Celform が読み込める %1 個を超えています</translation>
    </message>
    <message>
        <source>%1 names material %2, which does not exist</source>
        <translation>%1 が存在しないマテリアル %2 を参照しています</translation>
    </message>
    <message>
        <source>%1 has %2 texture coordinates for %3 vertices</source>
        <translation>%1 には %3 個の頂点に対してテクスチャ座標が %2 個あります</translation>
    </message>
    <message>
        <source>the file has no triangle primitive</source>
        <translation>ファイルに三角形のプリミティブがありません</translation>
    </message>
    <message>
        <source>the animation lasts %1 seconds, more than the %2 frames Celform can load at %3 frames per second</source>
        <translation>アニメーションの長さは %1 秒で、%3 fps では Celform が読み込める %2 フレームを超えます</translation>
    </message>
    <message>
        <source>%1 morph targets and %2 joints over %3 frames are more than Celform can hold</source>
        <translation>%3 フレームにわたるモーフターゲット %1 個とジョイント %2 個は Celform で扱える上限を超えています</translation>
    </message>
    <message>
        <source>morph target %1 of %2</source>
        <translation>%2 のモーフターゲット %1</translation>
    </message>
    <message>
        <source>%1 has %2 positions, the primitive %3</source>
        <translation>%1 の位置は %2 個ですが、プリミティブでは %3 個です</translation>
    </message>
    <message>
        <source>accessor %1 (%2): %3</source>
        <translation>アクセサー %1 (%2): %3</translation>
    </message>
    <message>
        <source>buffer view %1 does not exist</source>
        <translation>バッファービュー %1 が存在しません</translation>
    </message>
    <message>
        <source>buffer view %1 names buffer %2, which does not exist</source>
        <translation>バッファービュー %1 が存在しないバッファー %2 を参照しています</translation>
    </message>
    <message>
        <source>buffer view %1 covers bytes %2 to %3, but buffer %4 holds %5 bytes</source>
        <translation>バッファービュー %1 はバイト %2～%3 を指していますが、バッファー %4 は %5 バイトしかありません</translation>
    </message>
    <message>
        <source>buffer view %1 has a byteStride where none is allowed</source>
        <translation>バッファービュー %1 に、許可されていない byteStride があります</translation>
    </message>
    <message>
        <source>buffer view %1 has a byteStride of %2 for elements of %3 bytes</source>
        <translation>バッファービュー %1 の byteStride は %2 ですが、要素は %3 バイトです</translation>
    </message>
    <message>
        <source>%1 elements of %2 bytes from byte %3 do not fit in buffer view %4 (%5 bytes)</source>
        <translation>バイト %3 からの %2 バイトの要素 %1 個がバッファービュー %4（%5 バイト）に収まりません</translation>
    </message>
    <message>
        <source>type %1, expected %2</source>
        <translation>型が %1 です（%2 が必要です）</translation>
    </message>
    <message>
        <source>unknown component type %1</source>
        <translation>不明なコンポーネント型 %1 です</translation>
    </message>
    <message>
        <source>%1 elements without a buffer view</source>
        <translation>バッファービューのない要素 %1 個</translation>
    </message>
    <message>
        <source>%1 sparse elements of %2</source>
        <translation>%2 個中 %1 個のスパース要素</translation>
    </message>
    <message>
        <source>sparse indices of component type %1</source>
        <translation>コンポーネント型 %1 のスパースインデックス</translation>
    </message>
    <message>
        <source>a negative sparse byteOffset</source>
        <translation>スパースの byteOffset が負の値です</translation>
    </message>
    <message>
        <source>sparse element %1 replaces element %2 of %3</source>
        <translation>スパース要素 %1 が %3 個中の要素 %2 を置き換えています</translation>
    </message>
    <message>
        <source>%1 elements of %2 bytes cannot fit in buffer view %3 (%4 bytes)</source>
        <translation>%2 バイトの要素 %1 個はバッファービュー %3（%4 バイト）に収まりません</translation>
    </message>
    <message>
        <source>component type %1, expected unsigned integers</source>
        <translation>コンポーネント型が %1 です（符号なし整数が必要です）</translation>
    </message>
    <message>
        <source>node %1 has child %2, which does not exist</source>
        <translation>ノード %1 の子 %2 が存在しません</translation>
    </message>
    <message>
        <source>node %1 has more than one parent</source>
        <translation>ノード %1 に親が複数あります</translation>
    </message>
    <message>
        <source>the node hierarchy has a cycle</source>
        <translation>ノードの階層が循環しています</translation>
    </message>
    <message>
        <source>node %1 has a malformed transform</source>
        <translation>ノード %1 の変換が不正です</translation>
    </message>
    <message>
        <source>node %1 has a zero rotation quaternion</source>
        <translation>ノード %1 の回転クォータニオンがゼロです</translation>
    </message>
    <message>
        <source>animation channel %1 targets node %2, which does not exist</source>
        <translation>アニメーションチャンネル %1 の対象ノード %2 が存在しません</translation>
    </message>
    <message>
        <source>animation channel %1 moves node %2, which is given as a matrix (glTF allows only translation, rotation and scale on animated nodes)</source>
        <translation>アニメーションチャンネル %1 が行列で指定されたノード %2 を動かしています（glTF でアニメーションするノードに使えるのは移動、回転、スケールだけです）</translation>
    </message>
    <message>
        <source>animation channel %1 names sampler %2, which does not exist</source>
        <translation>アニメーションチャンネル %1 が存在しないサンプラー %2 を参照しています</translation>
    </message>
    <message>
        <source>animation sampler %1 has an unknown interpolation &quot;%2&quot;</source>
        <translation>アニメーションサンプラー %1 の補間「%2」は不明です</translation>
    </message>
    <message>
        <source>animation sampler %1</source>
        <translation>アニメーションサンプラー %1</translation>
    </message>
    <message>
        <source>animation sampler %1 has no keys</source>
        <translation>アニメーションサンプラー %1 にキーフレームがありません</translation>
    </message>
    <message>
        <source>animation sampler %1: key %2 has time %3, not after the key before it</source>
        <translation>アニメーションサンプラー %1: キーフレーム %2 の時刻 %3 が前のキーフレームより後になっていません</translation>
    </message>
    <message>
        <source>animation sampler %1 has %2 output values for %3 keys, expected %4</source>
        <translation>アニメーションサンプラー %1 にはキーフレーム %3 個に対して出力値が %2 個あります（%4 個が必要です）</translation>
    </message>
    <message>
        <source>animation sampler %1 has a value that is not a finite number</source>
        <translation>アニメーションサンプラー %1 に有限の数値でない値があります</translation>
    </message>
    <message>
        <source>unknown error</source>
        <translation>不明なエラー</translation>
    </message>
    <message>
        <source>this build cannot read glTF: its tinygltf functions come from %1, not from tinygltf&apos;s library (link TinyGLTF before Assimp)</source>
        <translation>このビルドでは glTF を読み込めません: tinygltf の関数が tinygltf のライブラリではなく %1 から来ています（Assimp より前に TinyGLTF をリンクしてください）</translation>
    </message>
    <message>
        <source>the file is larger than the 4 GB glTF allows</source>
        <translation>ファイルが glTF で許される 4 GB を超えています</translation>
    </message>
    <message>
        <source>its JSON is nested more than %1 levels deep, which no glTF file needs</source>
        <translation>JSON の入れ子が %1 階層を超えています（glTF ファイルでは必要のない深さです）</translation>
    </message>
    <message>
        <source>not a readable glTF file: %1</source>
        <translation>読み込み可能な glTF ファイルではありません: %1</translation>
    </message>
    <message>
        <source>the file needs the glTF extension %1, which Celform does not read</source>
        <translation>ファイルには Celform が読み込めない glTF 拡張 %1 が必要です</translation>
    </message>
    <message>
        <source>%1: the frame number is too long</source>
        <translation>%1: フレーム番号が長すぎます</translation>
    </message>
    <message>
        <source>the sequence has more than the %1 frames Celform can load</source>
        <translation>連番のフレームが、Celform が読み込める %1 フレームを超えています</translation>
    </message>
    <message>
        <source>%1 and %2 are both frame %3</source>
        <translation>%1 と %2 はどちらもフレーム %3 です</translation>
    </message>
    <message>
        <source>%1 triangles, the first frame (%2) has %3</source>
        <translation>三角形が %1 個ですが、最初のフレーム（%2）では %3 個です</translation>
    </message>
    <message>
        <source>triangle %1 is (%2, %3, %4), the first frame&apos;s (%5) is (%6, %7, %8)</source>
        <translation>三角形 %1 は (%2, %3, %4) ですが、最初のフレーム（%5）では (%6, %7, %8) です</translation>
    </message>
    <message>
        <source>not an animated base: use a .gltf or .glb file, or a numbered .obj, .ply or .off sequence (walk_0001.obj, or walk_####.obj)</source>
        <translation>アニメーションするベースモデルではありません: .gltf か .glb ファイル、または連番の .obj、.ply、.off（walk_0001.obj または walk_####.obj）を使用してください</translation>
    </message>
    <message>
        <source>no file matches the pattern</source>
        <translation>パターンに一致するファイルがありません</translation>
    </message>
    <message>
        <source>%1 frames of %2 vertices are more than Celform can hold</source>
        <translation>頂点 %2 個 × %1 フレームは Celform で扱える上限を超えています</translation>
    </message>
    <message>
        <source>%1 vertices, the first frame (%2) has %3</source>
        <translation>頂点が %1 個ですが、最初のフレーム（%2）では %3 個です</translation>
    </message>
    <message>
        <source>not a readable glTF file: its JSON cannot be read: %1 at byte %2%3</source>
        <translation>読み取れる glTF ファイルではありません: JSON を読めません: %1（バイト %2）%3</translation>
    </message>
    <message>
        <source> (NaN and Infinity are not JSON numbers)</source>
        <translation>（NaN と Infinity は JSON の数値ではありません）</translation>
    </message>
    <message numerus="yes">
        <source>and %n more</source>
        <translation>
            <numerusform>ほか %n 件</numerusform>
        </translation>
    </message>
    <message>
        <source>the sequence&apos;s numbers run from %1 to %2, more than the %3 frames Celform can load</source>
        <translation>シーケンスの番号は %1 から %2 まであり、Celform が読み込める %3 フレームを超えています</translation>
    </message>
    <message>
        <source>the sequence has no file numbered %1; each missing number holds the frame before it</source>
        <translation>シーケンスに番号 %1 のファイルがありません。欠けた番号はその前のフレームを保持します</translation>
    </message>
</context>
<context>
    <name>celform::model::BlendEvaluator</name>
    <message>
        <source>The key “%1” has no view direction (zero or not finite).</source>
        <translation>キー「%1」に視線方向がありません（ゼロまたは有限でない値です）。</translation>
    </message>
</context>
<context>
    <name>celform::model::Document</name>
    <message>
        <source>has %1 vertices, but the key deformations use vertex %2; a replacement base model needs the same vertex count and order</source>
        <translation>頂点数が %1 ですが、キー変形では頂点 %2 が使われています。置き換えるベースモデルは頂点数と頂点順序が同じである必要があります</translation>
    </message>
    <message>
        <source>Replace Base Model</source>
        <translation>ベースモデルを置き換え</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <source>Add Highlight Layer</source>
        <translation>ハイライトレイヤーを追加</translation>
    </message>
    <message>
        <source>Change Highlight Size</source>
        <translation>ハイライトのサイズを変更</translation>
    </message>
    <message>
        <source>Change Highlight Colour</source>
        <translation>ハイライトの色を変更</translation>
    </message>
    <message>
        <source>Change Off-Specular Cut</source>
        <translation>オフスペキュラーカットを変更</translation>
    </message>
    <message>
        <source>Change Highlight Operation</source>
        <translation>ハイライト操作を変更</translation>
    </message>
    <message>
        <source>Key Highlight</source>
        <translation>ハイライトのキーフレームを設定</translation>
    </message>
    <message>
        <source>base</source>
        <translation>ベース</translation>
    </message>
</context>
<context>
    <name>celform::model::DrawingEdits</name>
    <message>
        <source>Add Drawing “%1”</source>
        <translation>参照画「%1」を追加</translation>
    </message>
    <message>
        <source>Remove Drawing “%1”</source>
        <translation>参照画「%1」を削除</translation>
    </message>
    <message>
        <source>Rename Drawing to “%1”</source>
        <translation>参照画の名前を「%1」に変更</translation>
    </message>
    <message>
        <source>Set Drawing Opacity</source>
        <translation>参照画の不透明度を設定</translation>
    </message>
    <message>
        <source>Align Drawing “%1”</source>
        <translation>参照画「%1」の位置合わせ</translation>
    </message>
    <message>
        <source>Set Outline of “%1”</source>
        <translation>「%1」の輪郭を設定</translation>
    </message>
</context>
<context>
    <name>celform::model::Export</name>
    <message>
        <source>frames must be within ±%1</source>
        <translation>フレームは ±%1 の範囲内である必要があります</translation>
    </message>
    <message>
        <source>the first frame %1 is after the last frame %2</source>
        <translation>最初のフレーム %1 が最後のフレーム %2 より後です</translation>
    </message>
    <message>
        <source>no output file</source>
        <translation>出力ファイルが指定されていません</translation>
    </message>
    <message>
        <source>the aspect ratio must be positive</source>
        <translation>アスペクト比は正の値である必要があります</translation>
    </message>
    <message>
        <source>has no base model</source>
        <translation>ベースモデルがありません</translation>
    </message>
    <message>
        <source>glTF exports hold the keys as morph targets of the base model and take no subdivision; export pc2 or obj-seq with --subdivision</source>
        <translation>glTF の書き出しはキーをベースモデルのモーフターゲットとして持つため細分化できません。--subdivision は pc2 か obj-seq で書き出してください</translation>
    </message>
    <message>
        <source>blend shapes are written by usda exports only</source>
        <translation>ブレンドシェイプは usda の書き出しでのみ書き出されます</translation>
    </message>
    <message>
        <source>blend shapes hold the keys on the base model&apos;s vertices and take no subdivision</source>
        <translation>ブレンドシェイプはキーをベースモデルの頂点上に持つため細分割を取りません</translation>
    </message>
</context>
<context>
    <name>celform::model::ExrEncoder</name>
    <message>
        <source>an image of %1 x %2 pixels and %3 channels cannot be written</source>
        <translation>%1 x %2 ピクセル、%3 チャンネルの画像は書き出せません</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>メモリが足りません</translation>
    </message>
    <message>
        <source>channel %1 is not among those given</source>
        <translation>チャンネル %1 は渡されたチャンネルにありません</translation>
    </message>
    <message>
        <source>two channels have the same name</source>
        <translation>2 つのチャンネルが同じ名前です</translation>
    </message>
</context>
<context>
    <name>celform::model::FaceSetEdits</name>
    <message>
        <source>Paint Patch “%1”</source>
        <translation>パッチ「%1」をペイント</translation>
    </message>
    <message>
        <source>There is no base model to make a patch on.</source>
        <translation>パッチを作るベースモデルがありません。</translation>
    </message>
    <message>
        <source>A patch needs a name.</source>
        <translation>パッチには名前が必要です。</translation>
    </message>
    <message>
        <source>Patch “%1” names a face the base model does not have.</source>
        <translation>パッチ「%1」がベースモデルにない面を指しています。</translation>
    </message>
    <message>
        <source>Delete Patch “%1”</source>
        <translation>パッチ「%1」を削除</translation>
    </message>
    <message>
        <source>There is already a patch named “%1”.</source>
        <translation>「%1」という名前のパッチはすでにあります。</translation>
    </message>
    <message>
        <source>Rename Patch “%1”</source>
        <translation>パッチ「%1」の名前を変更</translation>
    </message>
    <message>
        <source>The highlight layer no longer exists.</source>
        <translation>このハイライトレイヤーはすでに存在しません。</translation>
    </message>
    <message>
        <source>New Patch “%1”</source>
        <translation>新しいパッチ「%1」</translation>
    </message>
    <message>
        <source>There is no base model to paint focal points on.</source>
        <translation>焦点をペイントするベースモデルがありません。</translation>
    </message>
    <message>
        <source>The importance must be between 0 and 1.</source>
        <translation>重要度は 0～1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>The strength must be above 0 and at most 1.</source>
        <translation>強さは 0 より大きく 1 以下で指定してください。</translation>
    </message>
    <message>
        <source>Paint Focal Points</source>
        <translation>焦点をペイント</translation>
    </message>
    <message>
        <source>The focal points name a face the base model does not have.</source>
        <translation>焦点がベースモデルにない面を指しています。</translation>
    </message>
    <message>
        <source>Clear Focal Points</source>
        <translation>焦点を消去</translation>
    </message>
    <message>
        <source>There is no base model to mark segments on.</source>
        <translation>セグメントを指定するベースモデルがありません。</translation>
    </message>
    <message>
        <source>Segment overrides take models of at most 16,777,216 triangles.</source>
        <translation>セグメントの上書きを使えるのは、三角形が 16,777,216 個以下のモデルだけです。</translation>
    </message>
    <message>
        <source>Segment overrides refused: %1.</source>
        <translation>セグメントの上書きを適用できません: %1。</translation>
    </message>
</context>
<context>
    <name>celform::model::HighlightEdits</name>
    <message>
        <source>The highlight layer no longer exists.</source>
        <translation>このハイライトレイヤーはすでに存在しません。</translation>
    </message>
    <message>
        <source>Add Highlight Layer</source>
        <translation>ハイライトレイヤーを追加</translation>
    </message>
    <message>
        <source>Add Window Highlight</source>
        <translation>窓のハイライトを追加</translation>
    </message>
    <message>
        <source>Add Crescent Highlight</source>
        <translation>三日月のハイライトを追加</translation>
    </message>
    <message>
        <source>Add Highlight Operation</source>
        <translation>ハイライト操作を追加</translation>
    </message>
    <message>
        <source>Move Highlight Operation</source>
        <translation>ハイライト操作を移動</translation>
    </message>
    <message>
        <source>Remove Highlight Operation</source>
        <translation>ハイライト操作を削除</translation>
    </message>
    <message>
        <source>Remove Highlight Layer “%1”</source>
        <translation>ハイライトレイヤー「%1」を削除</translation>
    </message>
    <message>
        <source>A highlight layer needs a name.</source>
        <translation>ハイライトレイヤーには名前が必要です。</translation>
    </message>
    <message>
        <source>There is already a highlight layer named “%1”.</source>
        <translation>「%1」という名前のハイライトレイヤーはすでにあります。</translation>
    </message>
    <message>
        <source>Rename Highlight Layer “%1”</source>
        <translation>ハイライトレイヤー「%1」の名前を変更</translation>
    </message>
    <message>
        <source>Highlight layer “%1”: %2</source>
        <translation>ハイライトレイヤー「%1」: %2</translation>
    </message>
    <message>
        <source>Delete Highlight Key</source>
        <translation>ハイライトのキーフレームを削除</translation>
    </message>
    <message>
        <source>A highlight is keyed at a finite frame.</source>
        <translation>ハイライトのキーフレームは有限のフレームに設定してください。</translation>
    </message>
    <message>
        <source>Rotate Highlight</source>
        <translation>ハイライトを回転</translation>
    </message>
    <message>
        <source>Scale Highlight</source>
        <translation>ハイライトを拡大縮小</translation>
    </message>
    <message>
        <source>Move Highlight</source>
        <translation>ハイライトを移動</translation>
    </message>
    <message>
        <source>There is no patch named “%1”.</source>
        <translation>「%1」という名前のパッチはありません。</translation>
    </message>
    <message>
        <source>Change Highlight Patch</source>
        <translation>ハイライトのパッチを変更</translation>
    </message>
    <message>
        <source>A highlight&apos;s guide needs a direction (not zero).</source>
        <translation>ハイライトのガイド方向にはゼロ以外のベクトルが必要です。</translation>
    </message>
    <message>
        <source>Change Highlight Guide</source>
        <translation>ハイライトのガイド方向を変更</translation>
    </message>
    <message>
        <source>Normal smoothing takes 0 to %1 rounds.</source>
        <translation>法線の平滑化の回数は 0～%1 の範囲で指定してください。</translation>
    </message>
    <message>
        <source>Change Highlight Smoothing</source>
        <translation>ハイライトの平滑化を変更</translation>
    </message>
    <message>
        <source>Show Highlight Layer</source>
        <translation>ハイライトレイヤーを表示</translation>
    </message>
    <message>
        <source>Hide Highlight Layer</source>
        <translation>ハイライトレイヤーを非表示</translation>
    </message>
    <message>
        <source>Change Highlight Combinations</source>
        <translation>ハイライトの組み合わせを変更</translation>
    </message>
</context>
<context>
    <name>celform::model::Highlights</name>
    <message>
        <source>epsilon must lie in (0, 1]</source>
        <translation>epsilon は (0, 1] の範囲内である必要があります</translation>
    </message>
    <message>
        <source>colour components must lie in [0, 1]</source>
        <translation>色の各成分は [0, 1] の範囲内である必要があります</translation>
    </message>
    <message>
        <source>the off-specular cut must lie in [-1, 1]</source>
        <translation>オフスペキュラーカットは [-1, 1] の範囲内である必要があります</translation>
    </message>
    <message>
        <source>the parameters of a %1 operation are out of range</source>
        <translation>%1 操作のパラメーターが範囲外です</translation>
    </message>
    <message>
        <source>combinations belong to the track, not to its keys</source>
        <translation>組み合わせはキーフレームごとではなく、トラックに対して設定する必要があります</translation>
    </message>
    <message>
        <source>a highlight layer has no name</source>
        <translation>名前のないハイライトレイヤーがあります</translation>
    </message>
    <message>
        <source>two highlight layers are named “%1”</source>
        <translation>「%1」という名前のハイライトレイヤーが 2 つあります</translation>
    </message>
    <message>
        <source>highlight layer “%1” uses the unknown face set “%2”</source>
        <translation>ハイライトレイヤー「%1」が不明なフェースセット「%2」を使用しています</translation>
    </message>
    <message>
        <source>highlight layer “%1” has a zero guide direction</source>
        <translation>ハイライトレイヤー「%1」のガイド方向がゼロベクトルです</translation>
    </message>
    <message>
        <source>highlight layer “%1” has no keyframe</source>
        <translation>ハイライトレイヤー「%1」にキーフレームがありません</translation>
    </message>
    <message>
        <source>highlight layer “%1” has keyframes out of order</source>
        <translation>ハイライトレイヤー「%1」のキーフレームの順序が正しくありません</translation>
    </message>
    <message>
        <source>highlight layer “%1”: %2</source>
        <translation>ハイライトレイヤー「%1」: %2</translation>
    </message>
    <message>
        <source>highlight layer “%1” combines with “%2”, which is not another layer</source>
        <translation>ハイライトレイヤー「%1」の組み合わせ先「%2」は、他のレイヤーではありません</translation>
    </message>
    <message>
        <source>highlight layer “%1” has normal smoothing outside [0, %2]</source>
        <translation>ハイライトレイヤー「%1」の法線平滑化が [0, %2] の範囲外です</translation>
    </message>
</context>
<context>
    <name>celform::model::ImageIo</name>
    <message>
        <source>not a valid SVG drawing</source>
        <translation>有効な SVG 画像ではありません</translation>
    </message>
    <message>
        <source>the SVG drawing has no size</source>
        <translation>SVG 画像にサイズが指定されていません</translation>
    </message>
    <message>
        <source>the SVG drawing is too large</source>
        <translation>SVG 画像が大きすぎます</translation>
    </message>
    <message>
        <source>images of type &quot;%1&quot; cannot be read</source>
        <translation>種類「%1」の画像は読み込めません</translation>
    </message>
    <message>
        <source>a temporary copy of the image cannot be written</source>
        <translation>画像の一時コピーを書き込めません</translation>
    </message>
    <message>
        <source>the image cannot be read: %1</source>
        <translation>画像を読み込めません: %1</translation>
    </message>
    <message>
        <source>the image has no pixels</source>
        <translation>画像にピクセルがありません</translation>
    </message>
    <message>
        <source>the image is too large (%1 x %2 pixels)</source>
        <translation>画像が大きすぎます（%1 × %2 ピクセル）</translation>
    </message>
    <message>
        <source>the image data is damaged or truncated: %1</source>
        <translation>画像データが破損しているか、途中で切れています: %1</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>ファイルが空です</translation>
    </message>
    <message>
        <source>unknown image format &quot;%1&quot;</source>
        <translation>不明な画像フォーマット「%1」です</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>ファイルが存在しません</translation>
    </message>
    <message>
        <source>the file cannot be opened: %1</source>
        <translation>ファイルを開けません: %1</translation>
    </message>
    <message>
        <source>the file cannot be read: %1</source>
        <translation>ファイルを読み込めません: %1</translation>
    </message>
    <message>
        <source>Drawings (%1)</source>
        <translation>参照画 (%1)</translation>
    </message>
    <message>
        <source>the file is not a regular file (a folder, pipe or device)</source>
        <translation>通常のファイルではありません（フォルダー、パイプ、デバイス）</translation>
    </message>
    <message>
        <source>the image is too large (%1 x %2 pixels; drawings may have up to %3 pixels a side and %4 million in all)</source>
        <translation>画像が大きすぎます（%1 x %2 ピクセル。絵は一辺 %3 ピクセル、合計 %4 百万ピクセルまでです）</translation>
    </message>
    <message>
        <source>the image is too large for its file (%1 x %2 pixels from %3 bytes): the file is damaged</source>
        <translation>ファイルの大きさに対して画像が大きすぎます（%3 バイトから %1 x %2 ピクセル）。ファイルが壊れています</translation>
    </message>
    <message>
        <source>the file cannot be written: %1</source>
        <translation>ファイルを書き込めません: %1</translation>
    </message>
    <message>
        <source>the importer&apos;s result is damaged</source>
        <translation>インポーターの結果が壊れています</translation>
    </message>
    <message>
        <source>a temporary folder for the importer cannot be made: %1</source>
        <translation>インポーター用の一時フォルダーを作成できません: %1</translation>
    </message>
    <message>
        <source>colour mode data</source>
        <translation>カラーモードデータ</translation>
    </message>
    <message>
        <source>image resources</source>
        <translation>画像リソース</translation>
    </message>
    <message>
        <source>layer and mask information</source>
        <translation>レイヤーとマスクの情報</translation>
    </message>
    <message>
        <source>the PSD file is truncated (it ends before its %1)</source>
        <translation>PSD ファイルが途中で切れています（%1 の前で終わっています）</translation>
    </message>
    <message>
        <source>the PSD file states %1 bytes of %2, but holds %3 bytes after that point</source>
        <translation>PSD ファイルは %2 が %1 バイトあるとしていますが、その位置以降には %3 バイトしかありません</translation>
    </message>
    <message>
        <source>the PNG file is truncated (it ends before its last chunk)</source>
        <translation>PNG ファイルが途中で切れています（最後のチャンクの前で終わっています）</translation>
    </message>
    <message>
        <source>the SVG drawing has text, which cannot be drawn without fonts here</source>
        <translation>SVG 図面にテキストがありますが、ここではフォントなしでは描けません</translation>
    </message>
    <message>
        <source>the SVG drawing has text and no fonts are installed (fontconfig finds none; install fonts-dejavu-core)</source>
        <translation>SVG 図面にテキストがありますが、フォントがインストールされていません（fontconfig が見つけられません。fonts-dejavu-core をインストールしてください）</translation>
    </message>
    <message>
        <source>the JPEG file is truncated (it ends before its end-of-image marker)</source>
        <translation>JPEG ファイルが途中で切れています（画像終端マーカーの前で終わっています）</translation>
    </message>
    <message>
        <source>images of type &quot;%1&quot; cannot be written</source>
        <translation>種類「%1」の画像は書き出せません</translation>
    </message>
    <message>
        <source>the encoder gave no bytes</source>
        <translation>エンコーダーがバイトを返しませんでした</translation>
    </message>
    <message>
        <source>the JPEG file has a damaged metadata segment (APP1, APP2 or APP13 without its name)</source>
        <translation>JPEG ファイルのメタデータセグメントが壊れています (APP1、APP2、APP13 に名前がありません)</translation>
    </message>
</context>
<context>
    <name>celform::model::ImportProcess</name>
    <message>
        <source>%1 GB</source>
        <translation>%1 GB</translation>
    </message>
    <message>
        <source>%1 MB</source>
        <translation>%1 MB</translation>
    </message>
    <message>
        <source>cannot be read: the importer (the celform program) was not found; set CELFORM_EXECUTABLE</source>
        <translation>読み込めません: インポーター（celform プログラム）が見つかりません。CELFORM_EXECUTABLE を設定してください</translation>
    </message>
    <message>
        <source>cannot be read: the importer (%1) cannot be started: %2</source>
        <translation>読み込めません: インポーター（%1）を起動できません: %2</translation>
    </message>
    <message>
        <source>the importer took longer than %1 s and was stopped (the limit is CELFORM_IMPORT_SECONDS)</source>
        <translation>インポーターが %1 秒を超えたため停止しました（上限は CELFORM_IMPORT_SECONDS）</translation>
    </message>
    <message>
        <source>the importer used more than %1 s of processor time and was stopped</source>
        <translation>インポーターが %1 秒を超える CPU 時間を使ったため停止しました</translation>
    </message>
    <message>
        <source>the importer crashed on it (signal %1, %2)</source>
        <translation>インポーターがこのファイルでクラッシュしました（シグナル %1、%2）</translation>
    </message>
    <message>
        <source>the importer refused it</source>
        <translation>インポーターが読み込みを拒否しました</translation>
    </message>
    <message>
        <source>the importer needs more than %1 of memory for it and was stopped (the limit is CELFORM_IMPORT_MEMORY_MB)</source>
        <translation>インポーターが %1 を超えるメモリを必要としたため停止しました（上限は CELFORM_IMPORT_MEMORY_MB）</translation>
    </message>
    <message>
        <source>the importer failed on it (exit code %1): %2</source>
        <translation>インポーターが失敗しました（終了コード %1）: %2</translation>
    </message>
</context>
<context>
    <name>celform::model::KeyEdits</name>
    <message>
        <source>Key “%1” already has this view direction; a second key needs a different direction (at least %2° apart).</source>
        <translation>キー「%1」がすでにこの視線方向を使用しています。別のキーには異なる方向（%2° 以上離れた方向）が必要です。</translation>
    </message>
    <message>
        <source>A key needs a view direction.</source>
        <translation>キーには視線方向が必要です。</translation>
    </message>
    <message>
        <source>Add Key “%1”</source>
        <translation>キー「%1」を追加</translation>
    </message>
    <message>
        <source>Import a base model before making keys.</source>
        <translation>キーを作成する前にベースモデルをインポートしてください。</translation>
    </message>
    <message>
        <source>The key&apos;s camera is not valid (eye, target and up must differ).</source>
        <translation>キーのカメラが無効です（カメラ位置、注視点、上方向はそれぞれ異なる必要があります）。</translation>
    </message>
    <message>
        <source>The key&apos;s camera sits at the centre of the model; move it away first.</source>
        <translation>キーのカメラがモデルの中心にあります。先にカメラを中心から離してください。</translation>
    </message>
    <message>
        <source>The drawing no longer exists.</source>
        <translation>この参照画はすでに存在しません。</translation>
    </message>
    <message>
        <source>Align the drawing “%1” first: its camera gives the key&apos;s view direction.</source>
        <translation>先に参照画「%1」の位置合わせを行ってください。そのカメラの向きがキーの視線方向になります。</translation>
    </message>
    <message>
        <source>Re-align Key “%1”</source>
        <translation>キー「%1」を再位置合わせ</translation>
    </message>
    <message>
        <source>Fit Camera to Drawing</source>
        <translation>カメラを参照画に合わせる</translation>
    </message>
    <message>
        <source>Unlink Key “%1”</source>
        <translation>キー「%1」のリンクを解除</translation>
    </message>
    <message>
        <source>Link Key “%1” to a Drawing</source>
        <translation>キー「%1」を参照画にリンク</translation>
    </message>
    <message>
        <source>Remove Key “%1”</source>
        <translation>キー「%1」を削除</translation>
    </message>
    <message>
        <source>Rename Key to “%1”</source>
        <translation>キーの名前を「%1」に変更</translation>
    </message>
    <message>
        <source>Enable Key “%1”</source>
        <translation>キー「%1」を有効化</translation>
    </message>
    <message>
        <source>Disable Key “%1”</source>
        <translation>キー「%1」を無効化</translation>
    </message>
    <message>
        <source>has %1 vertices, but the base model has %2: a key deformation needs the base model&apos;s vertex count and order</source>
        <translation>頂点数が %1 ですが、ベースモデルの頂点数は %2 です。キー変形にはベースモデルと同じ頂点数と頂点順序が必要です</translation>
    </message>
    <message>
        <source>its triangles differ from the base model&apos;s; only the vertex positions are used</source>
        <translation>三角形の構成がベースモデルと異なります。頂点位置のみを使用します</translation>
    </message>
    <message>
        <source>Import Deformation into “%1”</source>
        <translation>「%1」に変形をインポート</translation>
    </message>
    <message>
        <source>Fit Shape to Drawing</source>
        <translation>形状を参照画に合わせる</translation>
    </message>
    <message>
        <source>Choose a key to deform first (Scene panel, then Edit Key).</source>
        <translation>先に変形するキーを選んでください（「シーン」パネルで選択してから「ブラシでキーを編集」）。</translation>
    </message>
    <message>
        <source>The base model has no vertex %1.</source>
        <translation>ベースモデルに頂点 %1 はありません。</translation>
    </message>
    <message>
        <source>The brush radius must be a positive number.</source>
        <translation>ブラシ半径には正の数を指定してください。</translation>
    </message>
    <message>
        <source>The brush needs a valid camera (eye, target and up must differ).</source>
        <translation>ブラシには有効なカメラが必要です（カメラ位置、注視点、上方向はそれぞれ異なる必要があります）。</translation>
    </message>
    <message>
        <source>Brush “%1”</source>
        <translation>ブラシ「%1」</translation>
    </message>
    <message>
        <source>Set Mirror Plane</source>
        <translation>ミラー平面を設定</translation>
    </message>
</context>
<context>
    <name>celform::model::LookEdits</name>
    <message>
        <source>Change Blend Sharpness</source>
        <translation>ブレンドのシャープネスを変更</translation>
    </message>
    <message>
        <source>Change Unspecified Regions</source>
        <translation>未指定領域のモードを変更</translation>
    </message>
    <message>
        <source>Change Time Interpolation</source>
        <translation>時間の補間を変更</translation>
    </message>
    <message>
        <source>Change Shading Style</source>
        <translation>シェーディングスタイルを変更</translation>
    </message>
    <message>
        <source>Change Material Style</source>
        <translation>マテリアルのスタイルを変更</translation>
    </message>
    <message>
        <source>Change Light Type</source>
        <translation>ライトの種類を変更</translation>
    </message>
    <message>
        <source>Move Light</source>
        <translation>ライトを移動</translation>
    </message>
    <message>
        <source>The light changed while it was being optimised; run Optimise Light for Stereo again.</source>
        <translation>最適化の途中でライトが変更されました。もう一度「ステレオ用にライトを最適化」を実行してください。</translation>
    </message>
    <message>
        <source>The optimised light is not usable.</source>
        <translation>最適化したライトは使用できません。</translation>
    </message>
    <message>
        <source>Optimise Light for Stereo</source>
        <translation>ステレオ用にライトを最適化</translation>
    </message>
    <message>
        <source>Change Background Colour</source>
        <translation>背景色を変更</translation>
    </message>
    <message>
        <source>Change Toon Tones</source>
        <translation>トゥーンの階調を変更</translation>
    </message>
    <message>
        <source>Change Toon Evaluation</source>
        <translation>トゥーンの評価単位を変更</translation>
    </message>
    <message>
        <source>Change Gooch Shading</source>
        <translation>Gooch シェーディングを変更</translation>
    </message>
    <message>
        <source>Change Hatching</source>
        <translation>ハッチングを変更</translation>
    </message>
    <message>
        <source>Show Lines</source>
        <translation>線を表示</translation>
    </message>
    <message>
        <source>Hide Lines</source>
        <translation>線を非表示</translation>
    </message>
    <message>
        <source>Change Line Kinds</source>
        <translation>線の種類を変更</translation>
    </message>
    <message>
        <source>Change Line Style</source>
        <translation>線のスタイルを変更</translation>
    </message>
    <message>
        <source>Change Stereo Settings</source>
        <translation>ステレオ設定を変更</translation>
    </message>
    <message>
        <source>The render camera is not valid (eye, target and up must differ).</source>
        <translation>レンダーカメラが無効です（カメラ位置、注視点、上方向はそれぞれ異なる必要があります）。</translation>
    </message>
    <message>
        <source>Set Render Camera</source>
        <translation>レンダーカメラを設定</translation>
    </message>
    <message>
        <source>Remove Render Camera</source>
        <translation>レンダーカメラを削除</translation>
    </message>
    <message>
        <source>The look&apos;s toon tones are not valid.</source>
        <translation>ルックのトゥーンの階調設定が不正です。</translation>
    </message>
    <message>
        <source>Apply Look</source>
        <translation>ルックを適用</translation>
    </message>
    <message>
        <source>Change Subdivision</source>
        <translation>細分化の変更</translation>
    </message>
    <message>
        <source>Key Light at Frame %1</source>
        <translation>フレーム %1 でライトをキー</translation>
    </message>
    <message>
        <source>The light track changed while it was being optimised; run Optimise Light Along Shot again.</source>
        <translation>最適化中にライトトラックが変更されました。もう一度「ショット全体でライトを最適化」を実行してください。</translation>
    </message>
    <message>
        <source>Optimise Light Along Shot</source>
        <translation>ショット全体でライトを最適化</translation>
    </message>
</context>
<context>
    <name>celform::model::MeshIo</name>
    <message>
        <source>the file does not exist</source>
        <translation>ファイルが存在しません</translation>
    </message>
    <message>
        <source>the file cannot be opened: %1</source>
        <translation>ファイルを開けません: %1</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>ファイルが空です</translation>
    </message>
    <message>
        <source>the file cannot be read: %1</source>
        <translation>ファイルを読み込めません: %1</translation>
    </message>
    <message>
        <source>face %1 refers to vertex %2, but the file has %3 vertices</source>
        <translation>面 %1 が頂点 %2 を参照していますが、ファイルの頂点数は %3 です</translation>
    </message>
    <message>
        <source>1 face with fewer than three corners ignored</source>
        <translation>角が 3 つ未満の面を 1 個無視しました</translation>
    </message>
    <message numerus="yes">
        <source>%n faces with fewer than three corners ignored</source>
        <translation>
            <numerusform>角が 3 つ未満の面を %n 個無視しました</numerusform>
        </translation>
    </message>
    <message>
        <source>the header announces %1 vertices and %2 faces, more than the file holds</source>
        <translation>ヘッダーには頂点 %1 個、面 %2 個とありますが、ファイルにはそれだけのデータがありません</translation>
    </message>
    <message>
        <source>the file ends early, while reading %1</source>
        <translation>%1の読み込み中にファイルが終わっています</translation>
    </message>
    <message>
        <source>line %1: expected %2</source>
        <translation>%1 行目: %2が必要です</translation>
    </message>
    <message>
        <source>a vertex coordinate</source>
        <translation>頂点座標</translation>
    </message>
    <message>
        <source>a count</source>
        <translation>個数</translation>
    </message>
    <message>
        <source>a vertex index</source>
        <translation>頂点インデックス</translation>
    </message>
    <message>
        <source>a property value</source>
        <translation>プロパティ値</translation>
    </message>
    <message>
        <source>vertex %1 has a coordinate that is not a finite number</source>
        <translation>頂点 %1 の座標に有限でない数値があります</translation>
    </message>
    <message>
        <source>only three-dimensional OFF files are supported</source>
        <translation>3 次元の OFF ファイルのみサポートしています</translation>
    </message>
    <message>
        <source>binary OFF files are not supported</source>
        <translation>バイナリ形式の OFF ファイルはサポートしていません</translation>
    </message>
    <message>
        <source>not an OFF file (it does not start with &quot;OFF&quot;)</source>
        <translation>OFF ファイルではありません（&quot;OFF&quot; で始まっていません）</translation>
    </message>
    <message>
        <source>the header has a negative vertex or face count</source>
        <translation>ヘッダーの頂点数または面数が負の値です</translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 vertices</source>
        <translation>頂点 %2 個のうち %1 個を読んだところでファイルが終わっています</translation>
    </message>
    <message>
        <source>the file ends after %1 of %2 faces</source>
        <translation>面 %2 個のうち %1 個を読んだところでファイルが終わっています</translation>
    </message>
    <message>
        <source>face %1 has an invalid corner count %2</source>
        <translation>面 %1 の角の数 %2 が不正です</translation>
    </message>
    <message>
        <source>PLY header line %1: %2</source>
        <translation>PLY ヘッダー %1 行目: %2</translation>
    </message>
    <message>
        <source>not a PLY file (it does not start with &quot;ply&quot;)</source>
        <translation>PLY ファイルではありません（&quot;ply&quot; で始まっていません）</translation>
    </message>
    <message>
        <source>the PLY header has no end_header line</source>
        <translation>PLY ヘッダーに end_header 行がありません</translation>
    </message>
    <message>
        <source>incomplete format line</source>
        <translation>format 行が不完全です</translation>
    </message>
    <message>
        <source>unknown format &quot;%1&quot;</source>
        <translation>不明なフォーマット「%1」です</translation>
    </message>
    <message>
        <source>invalid element line</source>
        <translation>element 行が不正です</translation>
    </message>
    <message>
        <source>property before any element</source>
        <translation>element より前に property があります</translation>
    </message>
    <message>
        <source>unknown property type</source>
        <translation>不明なプロパティ型です</translation>
    </message>
    <message>
        <source>invalid property line</source>
        <translation>property 行が不正です</translation>
    </message>
    <message>
        <source>unknown keyword &quot;%1&quot;</source>
        <translation>不明なキーワード「%1」です</translation>
    </message>
    <message>
        <source>the PLY header has no format line</source>
        <translation>PLY ヘッダーに format 行がありません</translation>
    </message>
    <message>
        <source>the file is truncated: it ends inside the &quot;%1&quot; element</source>
        <translation>ファイルが途中で切れています（要素「%1」の途中で終わっています）</translation>
    </message>
    <message>
        <source>the face element has no vertex_indices list</source>
        <translation>face 要素に vertex_indices リストがありません</translation>
    </message>
    <message>
        <source>element &quot;%1&quot; row %2 has an invalid list length %3</source>
        <translation>要素「%1」の %2 行目のリスト長 %3 が不正です</translation>
    </message>
    <message>
        <source>the PLY file has no vertex element</source>
        <translation>PLY ファイルに vertex 要素がありません</translation>
    </message>
    <message>
        <source>the vertex element lacks an x, y or z property</source>
        <translation>vertex 要素に x、y、z のいずれかのプロパティがありません</translation>
    </message>
    <message>
        <source>line %1: vertex %2 has a coordinate that is not a finite number</source>
        <translation>%1 行目: 頂点 %2 の座標に有限でない数値があります</translation>
    </message>
    <message>
        <source>not a readable OBJ file: %1</source>
        <translation>読み込み可能な OBJ ファイルではありません: %1</translation>
    </message>
    <message>
        <source>face %1 is incomplete</source>
        <translation>面 %1 が不完全です</translation>
    </message>
    <message>
        <source>face %1 refers to texture coordinate %2, but the file has %3</source>
        <translation>面 %1 がテクスチャ座標 %2 を参照していますが、ファイル内のテクスチャ座標は %3 個です</translation>
    </message>
    <message>
        <source>some materials could not be read: %1</source>
        <translation>一部のマテリアルを読み込めませんでした: %1</translation>
    </message>
    <message>
        <source>the scene has more vertices than Celform can hold</source>
        <translation>シーンの頂点数が Celform で扱える上限を超えています</translation>
    </message>
    <message>
        <source>not a readable %1 file: %2</source>
        <translation>読み込み可能な %1 ファイルではありません: %2</translation>
    </message>
    <message>
        <source>1 point or line ignored</source>
        <translation>点または線を 1 個無視しました</translation>
    </message>
    <message numerus="yes">
        <source>%n points or lines ignored</source>
        <translation>
            <numerusform>点または線を %n 個無視しました</numerusform>
        </translation>
    </message>
    <message>
        <source>the file contains no vertices</source>
        <translation>ファイルに頂点がありません</translation>
    </message>
    <message>
        <source>the file contains no faces</source>
        <translation>ファイルに面がありません</translation>
    </message>
    <message>
        <source>the mesh is unusable: %1</source>
        <translation>メッシュを使用できません: %1</translation>
    </message>
    <message>
        <source>1 hole</source>
        <translation>穴 1 個</translation>
    </message>
    <message numerus="yes">
        <source>%n holes</source>
        <translation>
            <numerusform>穴 %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n components</source>
        <translation>
            <numerusform>連結成分 %n 個</numerusform>
        </translation>
    </message>
    <message>
        <source>1 non-manifold edge</source>
        <translation>非多様体エッジ 1 本</translation>
    </message>
    <message numerus="yes">
        <source>%n non-manifold edges</source>
        <translation>
            <numerusform>非多様体エッジ %n 本</numerusform>
        </translation>
    </message>
    <message>
        <source>1 edge with inconsistent face orientation</source>
        <translation>面の向きが揃っていないエッジ 1 本</translation>
    </message>
    <message numerus="yes">
        <source>%n edges with inconsistent face orientation</source>
        <translation>
            <numerusform>面の向きが揃っていないエッジ %n 本</numerusform>
        </translation>
    </message>
    <message>
        <source>1 degenerate face</source>
        <translation>縮退面 1 個</translation>
    </message>
    <message numerus="yes">
        <source>%n degenerate faces</source>
        <translation>
            <numerusform>縮退面 %n 個</numerusform>
        </translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>unknown mesh format &quot;%1&quot;; use one of: %2</source>
        <translation>不明なメッシュフォーマット「%1」です。次のいずれかを使用してください: %2</translation>
    </message>
    <message>
        <source>Meshes (%1)</source>
        <translation>メッシュ (%1)</translation>
    </message>
    <message>
        <source>cannot write &quot;%1&quot; files; use .obj or .ply</source>
        <translation>「%1」形式のファイルは書き出せません。.obj または .ply を使用してください</translation>
    </message>
    <message>
        <source>the file cannot be written: %1</source>
        <translation>ファイルを書き込めません: %1</translation>
    </message>
    <message>
        <source>the scene has more than the %1 triangles Celform can load</source>
        <translation>シーンの三角形が、Celform が読み込める %1 個を超えています</translation>
    </message>
    <message>
        <source>this is a folder, not a regular file</source>
        <translation>これはフォルダーで、通常のファイルではありません</translation>
    </message>
    <message>
        <source>this is not a regular file (a pipe, a socket or a device)</source>
        <translation>通常のファイルではありません（パイプ、ソケット、デバイス）</translation>
    </message>
    <message>
        <source>the file has %1 vertices, more than the %2 vertices Celform can load</source>
        <translation>ファイルには %1 個の頂点があり、Celform が読み込める %2 個を超えています</translation>
    </message>
    <message>
        <source>the file has %1 faces, more than the %2 triangles Celform can load</source>
        <translation>ファイルには %1 個の面があり、Celform が読み込める %2 個の三角形を超えています</translation>
    </message>
    <message>
        <source>the file&apos;s faces make %1 triangles, more than the %2 triangles Celform can load</source>
        <translation>ファイルの面は %1 個の三角形になり、Celform が読み込める %2 個を超えています</translation>
    </message>
    <message>
        <source>the header announces %1 vertices and %2 faces, more than the file holds and more than the %3 vertices Celform can load</source>
        <translation>ヘッダーは頂点 %1 個と面 %2 個を示していますが、ファイルの中身より多く、Celform が読み込める %3 個の頂点も超えています</translation>
    </message>
    <message>
        <source>the header announces %1 vertices and %2 faces, more than the file holds and more than the %3 triangles Celform can load</source>
        <translation>ヘッダーは頂点 %1 個と面 %2 個を示していますが、ファイルの中身より多く、Celform が読み込める %3 個の三角形も超えています</translation>
    </message>
    <message>
        <source>face %1 makes more than the %2 triangles Celform can load</source>
        <translation>面 %1 で三角形が Celform が読み込める %2 個を超えます</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is outside the folder of the OBJ file</source>
        <translation>&quot;%1&quot; は OBJ ファイルのフォルダーの外にあります</translation>
    </message>
    <message>
        <source>&quot;%1&quot; does not exist</source>
        <translation>&quot;%1&quot; は存在しません</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a regular file</source>
        <translation>&quot;%1&quot; は通常のファイルではありません</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is larger than %2 MB</source>
        <translation>&quot;%1&quot; は %2 MB より大きいファイルです</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be opened: %2</source>
        <translation>&quot;%1&quot; を開けません: %2</translation>
    </message>
    <message>
        <source>a second &quot;%1&quot; element (a PLY file has one)</source>
        <translation>二つ目の &quot;%1&quot; 要素があります（PLY ファイルには一つだけです）</translation>
    </message>
    <message>
        <source>element &quot;%1&quot; has %2 rows but no properties</source>
        <translation>要素 &quot;%1&quot; は %2 行ありますが、プロパティがありません</translation>
    </message>
    <message>
        <source>its first chunk states %1 bytes, but the file holds %2 bytes after its headers</source>
        <translation>最初のチャンクは %1 バイトとしていますが、ヘッダーの後には %2 バイトしかありません</translation>
    </message>
    <message>
        <source>the importer&apos;s result is damaged</source>
        <translation>インポーターの結果が壊れています</translation>
    </message>
    <message>
        <source>a temporary folder for the importer cannot be made: %1</source>
        <translation>インポーター用の一時フォルダーを作成できません: %1</translation>
    </message>
    <message>
        <source>the importer&apos;s result cannot be read: %1</source>
        <translation>インポーターの結果を読み込めません: %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; files do not keep their vertex order; use .obj, .ply or .off</source>
        <translation>「%1」形式のファイルは頂点順序を保持しません。.obj、.ply、.off を使用してください</translation>
    </message>
    <message>
        <source>it refers to “%1”, outside its folder; such references are not read unless CELFORM_ALLOW_OUTSIDE_REFERENCES=1 is set</source>
        <translation>フォルダの外にある “%1” を参照しています。CELFORM_ALLOW_OUTSIDE_REFERENCES=1 を設定しない限り、このような参照は読み込みません</translation>
    </message>
</context>
<context>
    <name>celform::model::OutputFile</name>
    <message>
        <source>could not be written: %1</source>
        <translation>書き込めませんでした: %1</translation>
    </message>
</context>
<context>
    <name>celform::model::PngEncoder</name>
    <message>
        <source>a PNG holds 1, 3 or 4 channels, not %1</source>
        <translation>PNG のチャンネル数は 1、3、4 のいずれかです (%1 ではありません)</translation>
    </message>
    <message>
        <source>the image is empty</source>
        <translation>画像が空です</translation>
    </message>
    <message>
        <source>the PNG encoder failed: out of memory</source>
        <translation>PNG エンコーダーが失敗しました: メモリが足りません</translation>
    </message>
    <message>
        <source>the PNG encoder failed: the compressed image does not fit</source>
        <translation>PNG エンコーダーが失敗しました: 圧縮した画像が収まりません</translation>
    </message>
</context>
<context>
    <name>celform::model::ProjectFile</name>
    <message>
        <source>is damaged: %1</source>
        <translation>破損しています: %1</translation>
    </message>
    <message>
        <source>the entry “%1” is missing or has the wrong type</source>
        <translation>項目「%1」が存在しないか、型が正しくありません</translation>
    </message>
    <message>
        <source>the entry “%1” is not a finite number</source>
        <translation>項目「%1」が有限の数値ではありません</translation>
    </message>
    <message>
        <source>the count “%1” is out of range</source>
        <translation>個数「%1」が範囲外です</translation>
    </message>
    <message>
        <source>the entry “%1” has the unknown value “%2”</source>
        <translation>項目「%1」の値「%2」は不明です</translation>
    </message>
    <message>
        <source>the data block “%1” is missing</source>
        <translation>データブロック「%1」がありません</translation>
    </message>
    <message>
        <source>the data block “%1” lies outside the file</source>
        <translation>データブロック「%1」がファイルの範囲外にあります</translation>
    </message>
    <message>
        <source>the data block “%1” has %2 bytes instead of %3</source>
        <translation>データブロック「%1」のサイズが %3 バイトではなく %2 バイトです</translation>
    </message>
    <message>
        <source>the data block “%1” fails its checksum</source>
        <translation>データブロック「%1」のチェックサムが一致しません</translation>
    </message>
    <message>
        <source>a texture coordinate index is out of range</source>
        <translation>テクスチャ座標のインデックスが範囲外です</translation>
    </message>
    <message>
        <source>a face material index is out of range</source>
        <translation>面のマテリアルインデックスが範囲外です</translation>
    </message>
    <message>
        <source>the base model is invalid (%1)</source>
        <translation>ベースモデルが不正です（%1）</translation>
    </message>
    <message>
        <source>key “%1” has a vertex index out of range or out of order</source>
        <translation>キー「%1」の頂点インデックスが範囲外か、順序が正しくありません</translation>
    </message>
    <message>
        <source>key “%1” has a non-finite offset</source>
        <translation>キー「%1」に有限でないオフセットがあります</translation>
    </message>
    <message>
        <source>an object id is not below next_id</source>
        <translation>オブジェクト ID が next_id 未満ではありません</translation>
    </message>
    <message>
        <source>does not exist</source>
        <translation>存在しません</translation>
    </message>
    <message>
        <source>could not be opened: %1</source>
        <translation>開けませんでした: %1</translation>
    </message>
    <message>
        <source>is empty</source>
        <translation>空のファイルです</translation>
    </message>
    <message>
        <source>is not a Celform project</source>
        <translation>Celform プロジェクトではありません</translation>
    </message>
    <message>
        <source>is truncated</source>
        <translation>ファイルが途中で切れています</translation>
    </message>
    <message>
        <source>was written by a newer version of Celform (file format %1; this version reads up to %2). Please update Celform to open it.</source>
        <translation>新しいバージョンの Celform で保存されています（ファイル形式 %1。このバージョンで読み込めるのは %2 までです）。開くには Celform を更新してください。</translation>
    </message>
    <message>
        <source>is damaged: the format version is 0</source>
        <translation>破損しています: フォーマットバージョンが 0 です</translation>
    </message>
    <message>
        <source>is truncated or damaged: its end marker is missing</source>
        <translation>途中で切れているか破損しています: 終端マーカーがありません</translation>
    </message>
    <message>
        <source>is damaged: its table of contents lies outside the file</source>
        <translation>破損しています: 目次がファイルの範囲外にあります</translation>
    </message>
    <message>
        <source>is damaged: its table of contents fails its checksum</source>
        <translation>破損しています: 目次のチェックサムが一致しません</translation>
    </message>
    <message>
        <source>the entry “%1” is not a 3D vector</source>
        <translation>項目「%1」が 3D ベクトルではありません</translation>
    </message>
    <message>
        <source>the entry “%1” is not finite</source>
        <translation>項目「%1」が有限の値ではありません</translation>
    </message>
    <message>
        <source>the entry “%1” holds something that is not a number</source>
        <translation>項目「%1」に数値でない値が含まれています</translation>
    </message>
    <message>
        <source>a material style names no material</source>
        <translation>マテリアル別のスタイルにマテリアルが指定されていません</translation>
    </message>
    <message>
        <source>the toon tones are not valid</source>
        <translation>トゥーンの階調設定が不正です</translation>
    </message>
    <message>
        <source>the shading offsets do not match the vertex count</source>
        <translation>シェーディングオフセットの数が頂点数と一致しません</translation>
    </message>
    <message>
        <source>a shading offset is not finite</source>
        <translation>有限でないシェーディングオフセットがあります</translation>
    </message>
    <message>
        <source>a highlight layer is not an object</source>
        <translation>ハイライトレイヤーがオブジェクト形式ではありません</translation>
    </message>
    <message>
        <source>the entry “mode” has the unknown value “%1”</source>
        <translation>項目「mode」の値「%1」は不明です</translation>
    </message>
    <message>
        <source>the highlight operation “%1” is unknown</source>
        <translation>不明なハイライト操作「%1」です</translation>
    </message>
    <message>
        <source>the highlight operation “%1” has %2 values instead of %3</source>
        <translation>ハイライト操作「%1」の値の数が %3 個ではなく %2 個です</translation>
    </message>
    <message>
        <source>a face set name is empty or used twice</source>
        <translation>面の集合の名前が空か重複しています</translation>
    </message>
    <message>
        <source>face set “%1” refers to a face out of range or out of order</source>
        <translation>面の集合「%1」に範囲外または順序の乱れた面があります</translation>
    </message>
    <message>
        <source>the render camera is not a camera (eye at the target, or up along the view)</source>
        <translation>レンダーカメラがカメラになっていません（視点が注視点と同じか、上方向が視線と平行）</translation>
    </message>
    <message>
        <source>two highlight layers have the same id</source>
        <translation>2 つのハイライトレイヤーの ID が同じです</translation>
    </message>
    <message>
        <source>the current frame is not a frame number</source>
        <translation>現在のフレームがフレーム番号になっていません</translation>
    </message>
    <message>
        <source>the entry “%1” is out of range</source>
        <translation>項目 “%1” が範囲外です</translation>
    </message>
    <message>
        <source>the entry “%1” is not a frame number</source>
        <translation>項目 “%1” はフレーム番号ではありません</translation>
    </message>
    <message>
        <source>the data block “%1” is used twice</source>
        <translation>データブロック “%1” が二度使われています</translation>
    </message>
    <message>
        <source>face set “%1” has more faces than the model</source>
        <translation>面セット “%1” の面がモデルより多くあります</translation>
    </message>
    <message>
        <source>key “%1” moves more vertices than the model has</source>
        <translation>キー “%1” はモデルの頂点数より多くの頂点を動かしています</translation>
    </message>
    <message>
        <source>is not a regular file (a folder, pipe or device)</source>
        <translation>通常のファイルではありません（フォルダー、パイプ、デバイス）</translation>
    </message>
    <message>
        <source>cannot be opened: not enough memory</source>
        <translation>開けません: メモリが足りません</translation>
    </message>
    <message>
        <source>the ridge threshold is negative</source>
        <translation>稜線のしきい値が負の値です</translation>
    </message>
    <message>
        <source>key “%1” has shading offsets that do not match the vertex count</source>
        <translation>キー「%1」のシェーディングオフセットの数が頂点数と一致しません</translation>
    </message>
    <message>
        <source>key “%1” has a shading offset that is not finite</source>
        <translation>キー「%1」に有限でないシェーディングオフセットがあります</translation>
    </message>
    <message>
        <source>key “%1” has shading offsets twice at frame %2</source>
        <translation>キー「%1」のフレーム %2 にシェーディングオフセットが重複しています</translation>
    </message>
    <message>
        <source>the camera path is invalid: %1</source>
        <translation>カメラパスが無効です: %1</translation>
    </message>
    <message>
        <source>the base animation&apos;s frames are out of range</source>
        <translation>ベースアニメーションのフレームが範囲外です</translation>
    </message>
    <message>
        <source>the base animation has too many joints</source>
        <translation>ベースアニメーションのジョイントが多すぎます</translation>
    </message>
    <message>
        <source>the base animation is invalid: %1</source>
        <translation>ベースアニメーションが無効です: %1</translation>
    </message>
    <message>
        <source>the scene time is invalid: %1</source>
        <translation>シーンの時間設定が無効です: %1</translation>
    </message>
    <message>
        <source>the base animation has no base model</source>
        <translation>ベースアニメーションにベースモデルがありません</translation>
    </message>
    <message>
        <source>was not saved: %1 holds a value that is not a finite number</source>
        <translation>保存されませんでした: %1 に有限でない値が含まれています</translation>
    </message>
    <message>
        <source>drawing “%1” has an opacity outside 0 to 1</source>
        <translation>参照画「%1」の不透明度が 0～1 の範囲外です</translation>
    </message>
    <message>
        <source>drawing “%1”: %2</source>
        <translation>参照画「%1」: %2</translation>
    </message>
    <message>
        <source>key “%1” has a view direction of zero length</source>
        <translation>キー「%1」の視線方向の長さがゼロです</translation>
    </message>
    <message>
        <source>the blend sharpness is not between 0 and %1</source>
        <translation>ブレンドのシャープネスが 0～%1 の範囲外です</translation>
    </message>
    <message>
        <source>drawing “%1” has the id %2 of another object</source>
        <translation>参照画「%1」の ID %2 は別のオブジェクトの ID です</translation>
    </message>
    <message>
        <source>key “%1” has the id %2 of another object</source>
        <translation>キー「%1」の ID %2 は別のオブジェクトの ID です</translation>
    </message>
    <message>
        <source>key “%1” is linked to drawing %2, which the project does not hold</source>
        <translation>キー「%1」が、プロジェクトにない参照画 %2 にリンクされています</translation>
    </message>
    <message>
        <source>is damaged: its header has unknown flags (%1)</source>
        <translation>破損しています: ヘッダーに不明なフラグ（%1）があります</translation>
    </message>
    <message>
        <source>is damaged: its format_version is not a version number</source>
        <translation>破損しています: format_version がバージョン番号ではありません</translation>
    </message>
    <message>
        <source>the mirror plane is not off, x, y or z</source>
        <translation>ミラー平面が off、x、y、z のいずれでもありません</translation>
    </message>
    <message>
        <source>the subdivision levels are out of range</source>
        <translation>細分化レベルが範囲外です</translation>
    </message>
    <message>
        <source>the light track is invalid: %1</source>
        <translation>ライトトラックが無効です: %1</translation>
    </message>
    <message>
        <source>the base animation&apos;s vertex frames are out of range</source>
        <translation>ベースアニメーションの頂点フレームが範囲外です</translation>
    </message>
</context>
<context>
    <name>celform::model::RasterModule</name>
    <message>
        <source>%1 is not in %2</source>
        <translation>%1 が %2 にありません</translation>
    </message>
    <message>
        <source>raster images cannot be read or written: the OpenImageIO module cannot be loaded (%1)</source>
        <translation>ラスター画像を読み書きできません: OpenImageIO モジュールを読み込めません（%1）</translation>
    </message>
</context>
<context>
    <name>celform::model::RenderJob</name>
    <message>
        <source>has no base model</source>
        <translation>ベースモデルがありません</translation>
    </message>
    <message>
        <source>not enough memory to render it</source>
        <translation>レンダーするメモリが足りません</translation>
    </message>
    <message>
        <source>the render failed</source>
        <translation>レンダーに失敗しました</translation>
    </message>
    <message>
        <source>subdivision level %1 turns %2 triangles into %3 and needs about %4 GB, more than the %5 GB available; choose a lower level</source>
        <translation>細分化レベル %1 では %2 個の三角形が %3 個になり、約 %4 GB 必要です。使える %5 GB を超えるので、低いレベルを選んでください</translation>
    </message>
</context>
<context>
    <name>celform::model::RenderOutput</name>
    <message>
        <source>has an unknown image type; use .png, .tif, .jpg or .exr</source>
        <translation>不明な画像形式です。.png、.tif、.jpg、.exr のいずれかを使用してください</translation>
    </message>
    <message>
        <source>could not be written: %1</source>
        <translation>書き込めませんでした: %1</translation>
    </message>
    <message>
        <source>all passes together need an .exr file</source>
        <translation>すべてのパスをまとめて書き出すには .exr ファイルが必要です</translation>
    </message>
    <message>
        <source>the analysis needs an .exr file</source>
        <translation>解析結果には .exr ファイルが必要です</translation>
    </message>
    <message>
        <source>the curvature does not match the shape</source>
        <translation>曲率が形状と一致しません</translation>
    </message>
    <message>
        <source>is not a render pass; use one of %1</source>
        <translation>はレンダーパスではありません。次のいずれかを使用してください: %1</translation>
    </message>
    <message>
        <source>could not be written: the render has no data passes</source>
        <translation>書き出せませんでした: レンダーにデータパスがありません</translation>
    </message>
    <message>
        <source>is an EXR, whose floats are not quantised</source>
        <translation>は EXR です。その浮動小数点値は量子化されません</translation>
    </message>
</context>
<context>
    <name>celform::model::ShadingEdits</name>
    <message>
        <source>Shading offsets need a base model.</source>
        <translation>シェーディングオフセットにはベースモデルが必要です。</translation>
    </message>
    <message>
        <source>There is no key to hold these shading offsets.</source>
        <translation>このシェーディングオフセットを保持するキーがありません。</translation>
    </message>
    <message>
        <source>Shading offsets refused: %1.</source>
        <translation>シェーディングオフセットを適用できません: %1。</translation>
    </message>
    <message>
        <source>Set Shading Offsets (%1)</source>
        <translation>シェーディングオフセットを設定（%1）</translation>
    </message>
    <message>
        <source>There is no key to clear shading offsets from.</source>
        <translation>シェーディングオフセットを消去するキーがありません。</translation>
    </message>
    <message>
        <source>Clear Shading Offsets (%1)</source>
        <translation>シェーディングオフセットを消去（%1）</translation>
    </message>
    <message>
        <source>There is no key whose shading offsets to smooth.</source>
        <translation>シェーディングオフセットを平滑化するキーがありません。</translation>
    </message>
    <message>
        <source>Smoothing takes 1 to %1 rounds, not %2.</source>
        <translation>平滑化の回数は 1～%1 の範囲で指定してください（%2 は無効です）。</translation>
    </message>
    <message>
        <source>Smooth Shading Offsets (%1)</source>
        <translation>シェーディングオフセットを平滑化（%1）</translation>
    </message>
    <message>
        <source>Choose a key to paint shading offsets into first.</source>
        <translation>先にシェーディングオフセットを描くキーを選んでください。</translation>
    </message>
    <message>
        <source>The brush needs a positive radius and a strength of zero or more.</source>
        <translation>ブラシには正の半径と 0 以上の強さが必要です。</translation>
    </message>
    <message>
        <source>The shape painted on does not have the base model&apos;s vertices.</source>
        <translation>描画先の形状の頂点がベースモデルと一致しません。</translation>
    </message>
    <message>
        <source>Paint Shading Offsets (%1)</source>
        <translation>シェーディングオフセットをペイント（%1）</translation>
    </message>
    <message>
        <source>Automatic Shading Offsets (%1)</source>
        <translation>自動シェーディングオフセット（%1）</translation>
    </message>
</context>
<context>
    <name>celform::model::ShadingLayers</name>
    <message>
        <source>%1 shading offsets for %2 vertices</source>
        <translation>頂点 %2 個に対してシェーディングオフセットが %1 個あります</translation>
    </message>
    <message>
        <source>a shading offset is not finite</source>
        <translation>有限でないシェーディングオフセットがあります</translation>
    </message>
</context>
<context>
    <name>celform::views::AlignTool</name>
    <message>
        <source>Shift+click inside the drawing to place its point.</source>
        <translation>参照画の内側を Shift + クリックして参照画側の点を配置してください。</translation>
    </message>
    <message>
        <source>Click on the model to place a model point; Shift+click places the drawing point.</source>
        <translation>モデル上をクリックしてモデル側の点を配置します。Shift + クリックで参照画側の点を配置します。</translation>
    </message>
    <message>
        <source>Click a feature on the model, then Shift+click the same feature on the drawing; six pairs or more, then Solve Camera.</source>
        <translation>モデル上の特徴的な箇所をクリックし、参照画上の同じ箇所を Shift + クリックします。6 組以上指定したら「カメラを推定」を実行します。</translation>
    </message>
    <message>
        <source>Show a drawing to align first.</source>
        <translation>先に位置合わせする参照画を表示してください。</translation>
    </message>
    <message>
        <source>%1 pairs of points so far; the camera needs at least six.</source>
        <translation>現在の対応点は %1 組です。カメラの推定には 6 組以上必要です。</translation>
    </message>
    <message>
        <source>The camera could not be solved: %1</source>
        <translation>カメラを推定できませんでした: %1</translation>
    </message>
    <message>
        <source>Aligning to “%1”: move the camera until the model matches the drawing (Alt+drag, the wheel, Alt+Shift+drag rolls, add Ctrl to snap to 15°; numpad 1/3/7 for the axis views; O: outline only). Esc finishes.</source>
        <translation>“%1” に合わせています: モデルが絵と重なるまでカメラを動かしてください（Alt+ドラッグ、ホイール、Alt+Shift+ドラッグで回転、Ctrl を加えると 15° 刻み。テンキー 1/3/7 で軸方向の視点。O: 輪郭線のみ）。Esc で終了。</translation>
    </message>
</context>
<context>
    <name>celform::views::AxisGizmo</name>
    <message>
        <source>Click an axis to look at the model from that side (numeric keypad 1, 3, 7; Ctrl for the opposite side)</source>
        <translation>軸をクリックすると、その方向からモデルを見ます（テンキー 1、3、7。Ctrl で反対側）</translation>
    </message>
</context>
<context>
    <name>celform::views::BrushTool</name>
    <message>
        <source>Choose a key to deform first (Scene panel, then Edit Key).</source>
        <translation>先に変形するキーを選んでください（「シーン」パネルで選択してから「ブラシでキーを編集」）。</translation>
    </message>
    <message>
        <source>Hold the cursor over the model to resize the brush there.</source>
        <translation>ブラシの大きさを変えるには、カーソルをモデルの上に置いてください。</translation>
    </message>
    <message>
        <source>Move the mouse to resize the brush; click or Enter to keep, Esc to cancel.</source>
        <translation>マウスを動かしてブラシの大きさを変えます。クリックか Enter で確定、Esc で取り消し。</translation>
    </message>
    <message>
        <source>The mirror finds no twin of this vertex across the %1 plane: only this side moves.</source>
        <translation>この頂点には %1 平面をはさんだミラーの対応点がありません: こちら側だけが動きます。</translation>
    </message>
</context>
<context>
    <name>celform::views::DepthAnalysisRunner</name>
    <message>
        <source>No base model to analyse</source>
        <translation>解析するベースモデルがありません</translation>
    </message>
    <message>
        <source>Not enough memory for the analysis at %1 x %2</source>
        <translation>%1 x %2 の解析に必要なメモリが足りません</translation>
    </message>
</context>
<context>
    <name>celform::views::DepthChart</name>
    <message>
        <source>Depth error (MSE) and the share of segments inside the window over the shot; click to go to a frame</source>
        <translation>ショット全体の深度誤差（MSE）とウィンドウ内のセグメントの割合。クリックでそのフレームへ移動します</translation>
    </message>
    <message>
        <source>Chart Shot analyses every frame of the scene</source>
        <translation>「ショットをグラフ化」でシーンの全フレームを解析します</translation>
    </message>
    <message>
        <source>MSE (max %1)</source>
        <translation>MSE（最大 %1）</translation>
    </message>
    <message>
        <source>inside the window (0-100 %)</source>
        <translation>ウィンドウ内（0-100 %）</translation>
    </message>
</context>
<context>
    <name>celform::views::DepthOverlay</name>
    <message>
        <source>saturates at ±%1</source>
        <translation>±%1 で飽和</translation>
    </message>
    <message>
        <source>K &gt; 0 (dome)</source>
        <translation>K &gt; 0（ドーム状）</translation>
    </message>
    <message>
        <source>K &lt; 0 (saddle)</source>
        <translation>K &lt; 0（鞍状）</translation>
    </message>
    <message>
        <source>seen farther than it is</source>
        <translation>実際より遠くに見える</translation>
    </message>
    <message>
        <source>seen nearer than it is</source>
        <translation>実際より近くに見える</translation>
    </message>
</context>
<context>
    <name>celform::views::DepthPanel</name>
    <message>
        <source>Overlay</source>
        <translation>オーバーレイ</translation>
    </message>
    <message>
        <source>None</source>
        <translation>なし</translation>
    </message>
    <message>
        <source>Show the picture without an overlay</source>
        <translation>オーバーレイなしで画像を表示します</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>セグメント</translation>
    </message>
    <message>
        <source>Parts of salient shape: neighbouring pixels with the same sign of Gaussian curvature and close depths, one colour each (segments under the minimum size are left out)</source>
        <translation>形状の目立つ部分: ガウス曲率の符号が同じで奥行きが近い隣接ピクセルのまとまりを 1 色ずつで表示します（最小サイズ未満のセグメントは除きます）</translation>
    </message>
    <message>
        <source>Gaussian curvature</source>
        <translation>ガウス曲率</translation>
    </message>
    <message>
        <source>Orange where the surface is dome-like (K &gt; 0), blue where it is saddle-like (K &lt; 0)</source>
        <translation>面がドーム状（K &gt; 0）の所はオレンジ、鞍状（K &lt; 0）の所は青</translation>
    </message>
    <message>
        <source>Depth error</source>
        <translation>奥行き誤差</translation>
    </message>
    <message>
        <source>How far the depth a viewer perceives (that of the nearest colour edge) is from the real depth: blue where the surface is seen farther than it is, orange where it is seen nearer</source>
        <translation>見る人が感じる奥行き（最も近い色の境界の奥行き）と実際の奥行きの差: 実際より遠くに見える所は青、近くに見える所はオレンジ</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>不透明度</translation>
    </message>
    <message>
        <source>How much the overlay covers the model</source>
        <translation>オーバーレイがモデルをどれだけ覆うか</translation>
    </message>
    <message>
        <source>Mean squared difference between perceived and real depth over the model&apos;s pixels (model units squared): lower reads better in stereo</source>
        <translation>モデルのピクセル全体での、感じる奥行きと実際の奥行きの差の二乗平均（モデル単位の二乗）: 小さいほど立体視で形が読み取りやすくなります</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>セグメント</translation>
    </message>
    <message>
        <source>Pixels</source>
        <translation>ピクセル</translation>
    </message>
    <message>
        <source>Ratio</source>
        <translation>明部の比率</translation>
    </message>
    <message>
        <source>In window</source>
        <translation>範囲内</translation>
    </message>
    <message>
        <source>Each segment&apos;s share of pixels shaded bright (N·L plus offset above the toon threshold); the shading line reads best when it is inside the window</source>
        <translation>各セグメントで明るく塗られたピクセルの割合（N·L とオフセットの和がトゥーンのしきい値以上）。範囲内にあるとき陰影の境界線が最も読み取りやすくなります</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>解析</translation>
    </message>
    <message>
        <source>Lenient (0.20–0.80)</source>
        <translation>緩い（0.20–0.80）</translation>
    </message>
    <message>
        <source>Medium (0.35–0.65)</source>
        <translation>中程度（0.35–0.65）</translation>
    </message>
    <message>
        <source>Strict (0.50)</source>
        <translation>厳しい（0.50）</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>カスタム</translation>
    </message>
    <message>
        <source>The bright/dark ratios a segment should have (thesis 5.0.3)</source>
        <translation>セグメントが持つべき明暗比（論文 5.0.3）</translation>
    </message>
    <message>
        <source>Ratio window</source>
        <translation>比率の範囲</translation>
    </message>
    <message>
        <source>Lowest acceptable bright ratio</source>
        <translation>許容する明部比率の下限</translation>
    </message>
    <message>
        <source>Highest acceptable bright ratio</source>
        <translation>許容する明部比率の上限</translation>
    </message>
    <message>
        <source>From, to</source>
        <translation>下限、上限</translation>
    </message>
    <message>
        <source> % of size</source>
        <translation> %（サイズ比）</translation>
    </message>
    <message>
        <source>Neighbouring pixels whose depths differ by this share of the model&apos;s bounding-box diagonal or more belong to different segments</source>
        <translation>奥行きの差がモデルのバウンディングボックス対角線のこの割合以上ある隣接ピクセルは別のセグメントになります</translation>
    </message>
    <message>
        <source>Depth step</source>
        <translation>奥行きの段差</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Smaller segments are dropped as noise (the thesis uses 64 pixels)</source>
        <translation>これより小さいセグメントはノイズとして除きます（論文では 64 ピクセル）</translation>
    </message>
    <message>
        <source>Smallest segment</source>
        <translation>最小セグメント</translation>
    </message>
    <message>
        <source>Depth error: —</source>
        <translation>奥行き誤差: —</translation>
    </message>
    <message>
        <source>Analysing…</source>
        <translation>解析中…</translation>
    </message>
    <message>
        <source>Depth error MSE: %1</source>
        <translation>奥行き誤差 MSE: %1</translation>
    </message>
    <message>
        <source>RMSE %1 model units · %2 of %3 segments inside the window · features on %4% of %5 model pixels · %6 x %7 px in %8 ms</source>
        <translation>RMSE %1 モデル単位 · %3 セグメント中 %2 が範囲内 · 特徴ピクセルはモデルの %5 ピクセルの %4% · %6 x %7 px を %8 ms で解析</translation>
    </message>
    <message>
        <source>Dome-like (K &gt; 0)</source>
        <translation>ドーム状（K &gt; 0）</translation>
    </message>
    <message>
        <source>Saddle-like (K &lt; 0)</source>
        <translation>鞍状（K &lt; 0）</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <source>No</source>
        <translation>いいえ</translation>
    </message>
    <message>
        <source>Light for Stereo</source>
        <translation>ステレオ用ライト</translation>
    </message>
    <message>
        <source>Gradient</source>
        <translation>勾配法</translation>
    </message>
    <message>
        <source>Annealing</source>
        <translation>アニーリング</translation>
    </message>
    <message>
        <source>Random</source>
        <translation>ランダム</translation>
    </message>
    <message>
        <source>Gradient moves the light from where you put it along the shading&apos;s derivative (predictable); annealing tries shrinking random moves; random tries independent lights and keeps the best</source>
        <translation>勾配法: 置いた位置からシェーディングの微分に沿ってライトを動かします（結果を予測しやすい）。アニーリング: 幅を狭めながらランダムに動かします。ランダム: 独立したライトを試して最良のものを残します</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>手法</translation>
    </message>
    <message>
        <source>Every segment alike</source>
        <translation>すべてのセグメントを同等に</translation>
    </message>
    <message>
        <source>By segment size</source>
        <translation>セグメントの大きさに応じて</translation>
    </message>
    <message>
        <source>Alike: small features such as dents count as much as the body (thesis figure 5.9); by size: large parts count more</source>
        <translation>同等: くぼみのような小さな部分も本体と同じだけ重視します（論文の図 5.9）。大きさに応じて: 大きな部分ほど重視します</translation>
    </message>
    <message>
        <source>Segments count</source>
        <translation>セグメントの重み</translation>
    </message>
    <message>
        <source>The layer of shading offsets the offset brush (Shift+O) and Edit &gt; Shading Offsets &gt; Automatic Shading Offsets write into</source>
        <translation>オフセットブラシ（Shift+O）と「編集」&gt;「シェーディングオフセット」&gt;「自動シェーディングオフセット」が書き込む、シェーディングオフセットのレイヤー</translation>
    </message>
    <message>
        <source>Shading offsets go into the %1.</source>
        <translation>シェーディングオフセットの書き込み先: %1。</translation>
    </message>
    <message>
        <source>Along the Shot</source>
        <translation>ショット全体</translation>
    </message>
    <message>
        <source>Chart Shot</source>
        <translation>ショットをグラフ化</translation>
    </message>
    <message>
        <source>Analyse every frame of the scene&apos;s range through the shot camera at the analysis size and chart the depth error</source>
        <translation>シーンの範囲の全フレームをショットカメラを通して解析サイズで解析し、深度誤差をグラフにします</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <source>Analysing frame %1 of %2…</source>
        <translation>フレーム %1 / %2 を解析しています…</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s), mean MSE %1</source>
        <translation>
            <numerusform>%n フレーム、平均 MSE %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>キャンセルしました</translation>
    </message>
    <message>
        <source>Changed since charted: Chart Shot again</source>
        <translation>グラフ化の後に変更されました: もう一度「ショットをグラフ化」してください</translation>
    </message>
    <message>
        <source>Analysing the shot…</source>
        <translation>ショットを解析しています…</translation>
    </message>
    <message>
        <source>Importance</source>
        <translation>重要度</translation>
    </message>
    <message>
        <source>The mean importance of the segment&apos;s faces (focal points, Look &gt; Focal Points): its weight in the light optimisation is multiplied by it</source>
        <translation>セグメントの面の重要度の平均（焦点、「ルック」&gt;「焦点」）: ライトの最適化でのセグメントの重みにこの値が掛けられます</translation>
    </message>
</context>
<context>
    <name>celform::views::FitGroup</name>
    <message>
        <source>Fit to Drawing</source>
        <translation>参照画に合わせる</translation>
    </message>
    <message>
        <source>How well the key meets its drawing&apos;s outline, seen through the key&apos;s camera at the drawing&apos;s frame: the overlap of the two filled shapes (IoU, 1 is a perfect match) and the mean distance between their outlines in drawing pixels. Measured on the control mesh&apos;s silhouette</source>
        <translation>参照画のフレームでキーのカメラから見たとき、キーが参照画の輪郭とどれだけ一致しているか: 塗りつぶした 2 つの形の重なり（IoU、1 で完全に一致）と、両者の輪郭間の平均距離（参照画のピクセル単位）。コントロールメッシュのシルエットで測定します</translation>
    </message>
    <message>
        <source>The faces Fit Shape may move: the whole model, or a painted face set</source>
        <translation>「形状を参照画に合わせる」で動かせる面: モデル全体、またはペイントした面セット</translation>
    </message>
    <message>
        <source>&amp;Region:</source>
        <translation>領域(&amp;R):</translation>
    </message>
    <message>
        <source>A painted face set whose vertices stay where they are</source>
        <translation>頂点を動かさずに固定する、ペイントした面セット</translation>
    </message>
    <message>
        <source>&amp;Pinned:</source>
        <translation>ピン留め(&amp;P):</translation>
    </message>
    <message>
        <source>How much of the fitted deformation Fit Shape applies: 1 all of it, 0.5 half way</source>
        <translation>「形状を参照画に合わせる」で合わせ込んだ変形をどれだけ適用するか: 1 ですべて、0.5 で半分</translation>
    </message>
    <message>
        <source>&amp;Strength:</source>
        <translation>強さ(&amp;S):</translation>
    </message>
    <message>
        <source>Whole model</source>
        <translation>モデル全体</translation>
    </message>
    <message>
        <source>None</source>
        <translation>なし</translation>
    </message>
    <message>
        <source>Link the key to a drawing to measure how well it meets it.</source>
        <translation>キーを参照画にリンクすると、どれだけ一致しているかを測定できます。</translation>
    </message>
    <message>
        <source>Against “%1”: the model is not in the key&apos;s view.</source>
        <translation>「%1」との比較: モデルがキーの視野に入っていません。</translation>
    </message>
    <message>
        <source>Against “%1”:
silhouette IoU %2
chamfer distance %3 px</source>
        <translation>「%1」との比較:
シルエットIoU %2
チャンファー距離 %3 px</translation>
    </message>
    <message>
        <source>&amp;Mirror (the brush&apos;s)</source>
        <translation>ミラー（ブラシと共通）(&amp;M)</translation>
    </message>
    <message>
        <source>Keep the fitted shape symmetric across the brush&apos;s mirror plane: one setting for both</source>
        <translation>フィットした形状をブラシのミラー平面に対して対称に保ちます（両方で一つの設定）</translation>
    </message>
</context>
<context>
    <name>celform::views::FrameTimeline</name>
    <message>
        <source>Frames of the animation: diamonds are the selected layer&apos;s keys; click or drag to move the current frame</source>
        <translation>アニメーションのフレームです。ひし形は選択したレイヤーのキーフレームを示します。クリックまたはドラッグで現在のフレームを移動します</translation>
    </message>
</context>
<context>
    <name>celform::views::HighlightPanel</name>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>alpha: moves the highlight along du</source>
        <translation>alpha: ハイライトを du 方向に移動します</translation>
    </message>
    <message>
        <source>β</source>
        <translation>β</translation>
    </message>
    <message>
        <source>beta: moves the highlight along dv</source>
        <translation>beta: ハイライトを dv 方向に移動します</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>Angle in degrees, du turning towards dv: turns the frame of later operations</source>
        <translation>角度（度、du から dv へ向かう回転が正）: 以降の操作の座標系を回転します</translation>
    </message>
    <message>
        <source>δ</source>
        <translation>δ</translation>
    </message>
    <message>
        <source>delta in [0, 1]: stretches the area along du</source>
        <translation>delta（[0, 1]）: 領域を du 方向に引き伸ばします</translation>
    </message>
    <message>
        <source>γ1</source>
        <translation>γ1</translation>
    </message>
    <message>
        <source>gamma1 &gt;= 0: cuts the area across du</source>
        <translation>gamma1（&gt;= 0）: du と交差する切れ目で領域を分割します</translation>
    </message>
    <message>
        <source>γ2</source>
        <translation>γ2</translation>
    </message>
    <message>
        <source>gamma2 &gt;= 0: cuts the area across dv</source>
        <translation>gamma2（&gt;= 0）: dv と交差する切れ目で領域を分割します</translation>
    </message>
    <message>
        <source>σ</source>
        <translation>σ</translation>
    </message>
    <message>
        <source>sigma in [0, 1]: squareness of the area (about 0.2 is squarest)</source>
        <translation>sigma（[0, 1]）: 領域の四角さ（0.2 前後で最も四角くなります）</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>n &gt;= 1: exponent of the squaring</source>
        <translation>n（&gt;= 1）: 四角化の指数</translation>
    </message>
    <message>
        <source>Translate</source>
        <translation>移動</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>回転</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>方向スケール</translation>
    </message>
    <message>
        <source>Split</source>
        <translation>分割</translation>
    </message>
    <message>
        <source>Square</source>
        <translation>四角化</translation>
    </message>
    <message>
        <source>Layers</source>
        <translation>レイヤー</translation>
    </message>
    <message>
        <source>Highlight layers, later ones drawn over earlier ones. Double-click to rename; unchecked layers are drawn only as operands of other layers&apos; combinations</source>
        <translation>ハイライトレイヤーです。後のレイヤーほど手前に描画されます。ダブルクリックで名前を変更できます。チェックを外したレイヤーは、他のレイヤーの組み合わせの対象としてのみ描画されます</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>追加(&amp;A)</translation>
    </message>
    <message>
        <source>Add a highlight layer with a key at the current frame</source>
        <translation>現在のフレームにキーフレームを持つハイライトレイヤーを追加します</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>削除(&amp;R)</translation>
    </message>
    <message>
        <source>Remove the selected layer and its use in other layers&apos; combinations</source>
        <translation>選択したレイヤーを削除し、他のレイヤーの組み合わせからも取り除きます</translation>
    </message>
    <message>
        <source>Highlight %1</source>
        <translation>ハイライト %1</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>キーフレーム</translation>
    </message>
    <message>
        <source>Go to the previous key of the layer</source>
        <translation>レイヤーの前のキーフレームへ移動します</translation>
    </message>
    <message>
        <source>Current frame: parameters show the layer at this frame, and edits key it here</source>
        <translation>現在のフレーム: パラメーターにはこのフレームでのレイヤーの値が表示され、編集するとこのフレームにキーフレームが設定されます</translation>
    </message>
    <message>
        <source>Go to the next key of the layer</source>
        <translation>レイヤーの次のキーフレームへ移動します</translation>
    </message>
    <message>
        <source>of </source>
        <translation>/ </translation>
    </message>
    <message>
        <source>Frame:</source>
        <translation>フレーム:</translation>
    </message>
    <message>
        <source>&amp;Key</source>
        <translation>キーを設定(&amp;K)</translation>
    </message>
    <message>
        <source>Set a key of all the layer&apos;s parameters at the current frame</source>
        <translation>レイヤーのすべてのパラメーターについて、現在のフレームにキーフレームを設定します</translation>
    </message>
    <message>
        <source>&amp;Delete Key</source>
        <translation>キーを削除(&amp;D)</translation>
    </message>
    <message>
        <source>Remove the layer&apos;s key at the current frame (a layer keeps at least one key)</source>
        <translation>現在のフレームにあるレイヤーのキーフレームを削除します（レイヤーには少なくとも 1 つのキーフレームが残ります）</translation>
    </message>
    <message>
        <source>Parameters at this frame</source>
        <translation>このフレームのパラメーター</translation>
    </message>
    <message>
        <source>Colour of the highlight (keyed)</source>
        <translation>ハイライトの色（キーフレーム対象）</translation>
    </message>
    <message>
        <source>&amp;Colour:</source>
        <translation>色(&amp;C):</translation>
    </message>
    <message>
        <source>Highlight Colour</source>
        <translation>ハイライトの色</translation>
    </message>
    <message>
        <source>epsilon: size of the area where (N, H) &gt; 1 - epsilon (keyed)</source>
        <translation>epsilon: (N, H) &gt; 1 - epsilon となる領域のサイズ（キーフレーム対象）</translation>
    </message>
    <message>
        <source>&amp;Epsilon:</source>
        <translation>イプシロン(&amp;E):</translation>
    </message>
    <message>
        <source>Off-specular cut: no highlight where N·L is at most this value; -1 turns it off (keyed)</source>
        <translation>オフスペキュラーカット: N·L がこの値以下の部分にはハイライトを表示しません。-1 でオフになります（キーフレーム対象）</translation>
    </message>
    <message>
        <source>Off-specular c&amp;ut:</source>
        <translation>オフスペキュラーカット(&amp;U):</translation>
    </message>
    <message>
        <source>Face set the highlight may appear on (not keyed)</source>
        <translation>ハイライトを表示できるフェースセット（キーフレーム対象外）</translation>
    </message>
    <message>
        <source>&amp;Patch:</source>
        <translation>パッチ(&amp;P):</translation>
    </message>
    <message>
        <source>Guide direction (x, y, z): the u axis of the highlight on models without UVs (not keyed)</source>
        <translation>ガイド方向（x, y, z）: UV のないモデルでのハイライトの u 軸（キーフレーム対象外）</translation>
    </message>
    <message>
        <source>&amp;Guide:</source>
        <translation>ガイド方向(&amp;G):</translation>
    </message>
    <message>
        <source>Operations (in order)</source>
        <translation>操作（適用順）</translation>
    </message>
    <message>
        <source>Add Operation</source>
        <translation>操作を追加</translation>
    </message>
    <message>
        <source>Append an operation on the highlight&apos;s vector field to every key of the layer</source>
        <translation>ハイライトのベクトル場に対する操作を、レイヤーのすべてのキーフレームの末尾に追加します</translation>
    </message>
    <message>
        <source>Combinations</source>
        <translation>組み合わせ</translation>
    </message>
    <message>
        <source>Add Combination</source>
        <translation>組み合わせを追加</translation>
    </message>
    <message>
        <source>Unite this layer&apos;s area with, or subtract from it, another layer&apos;s area at the same frame</source>
        <translation>同じフレームでの別のレイヤーの領域を、このレイヤーの領域に加えるか、このレイヤーの領域から差し引きます</translation>
    </message>
    <message>
        <source> (keyed)</source>
        <translation>（キーフレーム対象）</translation>
    </message>
    <message>
        <source>Move the operation earlier</source>
        <translation>操作を前に移動します</translation>
    </message>
    <message>
        <source>Move the operation later</source>
        <translation>操作を後ろに移動します</translation>
    </message>
    <message>
        <source>✕</source>
        <translation>✕</translation>
    </message>
    <message>
        <source>Remove the operation from every key</source>
        <translation>すべてのキーフレームからこの操作を削除します</translation>
    </message>
    <message>
        <source>Union with</source>
        <translation>和をとる</translation>
    </message>
    <message>
        <source>Subtract</source>
        <translation>差し引く</translation>
    </message>
    <message>
        <source>Union adds the other layer&apos;s area; Subtract cuts it out of this layer&apos;s area</source>
        <translation>「和をとる」では別のレイヤーの領域を加え、「差し引く」ではこのレイヤーの領域から別のレイヤーの領域を切り取ります</translation>
    </message>
    <message>
        <source>The other layer, at the same frame</source>
        <translation>組み合わせる別のレイヤー（同じフレームでの状態を使用）</translation>
    </message>
    <message>
        <source>Remove this combination</source>
        <translation>この組み合わせを削除します</translation>
    </message>
    <message>
        <source>Checked: drawn; unchecked: used only in other layers&apos; combinations</source>
        <translation>オン: 描画します。オフ: 他のレイヤーの組み合わせにのみ使用します</translation>
    </message>
    <message>
        <source>All faces</source>
        <translation>すべての面</translation>
    </message>
    <message>
        <source>Edit in &amp;Viewport</source>
        <translation>ビューポートで編集(&amp;V)</translation>
    </message>
    <message>
        <source>Drag on the model to move the highlight; Shift+drag rotates it, Ctrl+drag scales it (keyed at the current frame)</source>
        <translation>モデル上をドラッグしてハイライトを移動します。Shift+ドラッグで回転、Ctrl+ドラッグで拡大縮小します（現在のフレームにキーフレームを設定）</translation>
    </message>
    <message>
        <source>&amp;Preset</source>
        <translation>プリセット(&amp;P)</translation>
    </message>
    <message>
        <source>Add a shaped highlight to start from, on the selected layer&apos;s patch</source>
        <translation>選択中のレイヤーのパッチ上に、出発点となる形のハイライトを追加します</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>窓(&amp;W)</translation>
    </message>
    <message>
        <source>Rotation, directional scaling and split on a nearly flat part: the car window of the paper&apos;s Figure 5</source>
        <translation>ほぼ平らな部分での回転・方向スケーリング・分割: 論文の図 5 の車の窓</translation>
    </message>
    <message>
        <source>&amp;Crescent</source>
        <translation>三日月(&amp;C)</translation>
    </message>
    <message>
        <source>A highlight minus a hidden, shifted copy of itself: the crescent of the paper&apos;s Figure 6</source>
        <translation>ハイライトから、非表示でずらした自身の複製を引いたもの: 論文の図 6 の三日月</translation>
    </message>
    <message>
        <source>Paint</source>
        <translation>ペイント</translation>
    </message>
    <message>
        <source>Paint the layer&apos;s patch on the model: drag adds faces, Ctrl+drag removes them, [ and ] change the radius. A layer on all faces gets a new patch first.</source>
        <translation>レイヤーのパッチをモデル上に描きます: ドラッグで面を追加、Ctrl+ドラッグで除去、[ と ] で半径を変更。全面のレイヤーにはまず新しいパッチを作ります。</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>New, rename or delete patches</source>
        <translation>パッチの新規作成・名前変更・削除</translation>
    </message>
    <message>
        <source>&amp;New Patch</source>
        <translation>新しいパッチ(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Rename Patch…</source>
        <translation>パッチの名前を変更(&amp;R)…</translation>
    </message>
    <message>
        <source>Rename Patch</source>
        <translation>パッチの名前を変更</translation>
    </message>
    <message>
        <source>Patch name:</source>
        <translation>パッチ名:</translation>
    </message>
    <message>
        <source>&amp;Delete Patch</source>
        <translation>パッチを削除(&amp;D)</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <source>Rounds of normal smoothing over the patch: the highlight sees a smooth surface, as on the paper&apos;s spline patches, and coarse meshes give clean shapes. Paint thin parts (an ear) one side at a time: smoothing mixes the normals of both sides (not keyed)</source>
        <translation>パッチ上で法線を平滑化する回数: 論文のスプラインパッチのようにハイライトが滑らかな面を見るので、粗いメッシュでもきれいな形になります。薄い部分（耳など）は片面ずつ描いてください。平滑化は両面の法線を混ぜます（キーなし）</translation>
    </message>
    <message>
        <source>&amp;Smooth normals:</source>
        <translation>法線の平滑化(&amp;S):</translation>
    </message>
    <message>
        <source>The viewport draws the first %1 visible layers and, of each, %2 operations and %3 combinations; the rest shows in renders (celform render).</source>
        <translation>ビューポートが描くのは表示中の最初の %1 レイヤーと、それぞれの %2 個の操作・%3 個の組み合わせまでです。残りはレンダー（celform render）に表示されます。</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>窓</translation>
    </message>
    <message>
        <source>Crescent cut</source>
        <translation>三日月の切り抜き</translation>
    </message>
    <message>
        <source>Crescent</source>
        <translation>三日月</translation>
    </message>
    <message>
        <source>%1 patch</source>
        <translation>%1 のパッチ</translation>
    </message>
    <message>
        <source>The scene&apos;s last frame (set the range in the Timeline)</source>
        <translation>シーンの最後のフレーム（範囲はタイムラインで設定します）</translation>
    </message>
    <message>
        <source>Mirror</source>
        <translation>ミラー</translation>
    </message>
    <message>
        <source>Paint the mirror image across the project&apos;s mirror plane too (the brush&apos;s plane, Properties &gt; Mirror)</source>
        <translation>プロジェクトのミラー平面 (ブラシの平面、プロパティ &gt; ミラー) をまたいだ鏡像も塗ります</translation>
    </message>
</context>
<context>
    <name>celform::views::LookPanel</name>
    <message>
        <source>Shading</source>
        <translation>シェーディング</translation>
    </message>
    <message>
        <source>Toon</source>
        <translation>トゥーン</translation>
    </message>
    <message>
        <source>Gooch warm/cool</source>
        <translation>Gooch（暖色/寒色）</translation>
    </message>
    <message>
        <source>Comic hatching</source>
        <translation>コミック調ハッチング</translation>
    </message>
    <message>
        <source>Lambert</source>
        <translation>ランバート</translation>
    </message>
    <message>
        <source>Toon: flat tones; Gooch: warm and cool lights; Comic: shadows drawn as strokes; Lambert: plain diffuse shading for modelling</source>
        <translation>トゥーン: フラットな階調。Gooch: 暖色と寒色のライト。コミック: 影をストロークで描画。ランバート: モデリング用のシンプルな拡散シェーディング</translation>
    </message>
    <message>
        <source>&amp;Style:</source>
        <translation>スタイル(&amp;S):</translation>
    </message>
    <message>
        <source>The style applies to every material, or to one material only</source>
        <translation>スタイルをすべてのマテリアルに適用するか、1 つのマテリアルだけに適用するかを選びます</translation>
    </message>
    <message>
        <source>&amp;Applies to:</source>
        <translation>適用先(&amp;A):</translation>
    </message>
    <message>
        <source>All materials</source>
        <translation>すべてのマテリアル</translation>
    </message>
    <message>
        <source>Directional</source>
        <translation>平行光源</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点光源</translation>
    </message>
    <message>
        <source>Directional: the vector points from the model towards the light. Point: the light&apos;s position in model space.</source>
        <translation>平行光源: ベクトルはモデルからライトに向かう方向です。点光源: ベクトルはモデル空間でのライトの位置です。</translation>
    </message>
    <message>
        <source>&amp;Light:</source>
        <translation>ライト(&amp;L):</translation>
    </message>
    <message>
        <source>Light vector (x, y, z)</source>
        <translation>ライトのベクトル（x, y, z）</translation>
    </message>
    <message>
        <source>Light &amp;vector:</source>
        <translation>ライトのベクトル(&amp;V):</translation>
    </message>
    <message>
        <source>&amp;Background:</source>
        <translation>背景(&amp;B):</translation>
    </message>
    <message>
        <source>Colour behind the model</source>
        <translation>モデルの背後に表示する色</translation>
    </message>
    <message>
        <source>Toon tones</source>
        <translation>トゥーンの階調</translation>
    </message>
    <message>
        <source>Per pixel</source>
        <translation>ピクセル単位</translation>
    </message>
    <message>
        <source>Per vertex (32-entry table)</source>
        <translation>頂点単位（32 エントリのテーブル）</translation>
    </message>
    <message>
        <source>Per face</source>
        <translation>面単位</translation>
    </message>
    <message>
        <source>Where N·L is evaluated: per pixel gives crisp tone boundaries; per vertex through a 32-entry table interpolates across triangles (the comic renderer&apos;s way); per face shows each triangle&apos;s tone</source>
        <translation>N·L を評価する単位です。ピクセル単位では階調の境界がくっきりします。頂点単位では 32 エントリのテーブルを介して三角形内を補間します（コミックレンダラーの方式）。面単位では三角形ごとに 1 つの階調を表示します</translation>
    </message>
    <message>
        <source>&amp;Evaluation:</source>
        <translation>評価単位(&amp;E):</translation>
    </message>
    <message>
        <source>Number of flat tones</source>
        <translation>フラットな階調の数</translation>
    </message>
    <message>
        <source>&amp;Tones:</source>
        <translation>階調数(&amp;T):</translation>
    </message>
    <message>
        <source>By material hue (automatic)</source>
        <translation>マテリアルの色相に合わせる（自動）</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>既定</translation>
    </message>
    <message>
        <source>White (no warm light)</source>
        <translation>白（暖色ライトなし）</translation>
    </message>
    <message>
        <source>Purple (stronger cool)</source>
        <translation>紫（寒色を強める）</translation>
    </message>
    <message>
        <source>Red (more cool, less warm)</source>
        <translation>赤（寒色を強め、暖色を弱める）</translation>
    </message>
    <message>
        <source>The hue-adaptive rules of View-Dependent Geometry, section 3.2.4, as starting points</source>
        <translation>論文「View-Dependent Geometry」3.2.4 節の色相に応じた規則を、調整の出発点として使用します</translation>
    </message>
    <message>
        <source>&amp;Preset:</source>
        <translation>プリセット(&amp;P):</translation>
    </message>
    <message>
        <source>C = ka·Cbase + (l1·n)(Cwarm − Cbase·k1)·k2 + (l2·n)(Ccool − Cbase·k3)·k4</source>
        <translation>C = ka·Cbase + (l1·n)(Cwarm − Cbase·k1)·k2 + (l2·n)(Ccool − Cbase·k3)·k4</translation>
    </message>
    <message>
        <source>&amp;Warm:</source>
        <translation>暖色(&amp;W):</translation>
    </message>
    <message>
        <source>Warm light colour</source>
        <translation>暖色ライトの色</translation>
    </message>
    <message>
        <source>&amp;Cool:</source>
        <translation>寒色(&amp;C):</translation>
    </message>
    <message>
        <source>Cool light colour</source>
        <translation>寒色ライトの色</translation>
    </message>
    <message>
        <source>S&amp;pacing:</source>
        <translation>間隔(&amp;P):</translation>
    </message>
    <message>
        <source>Distance between strokes, model units</source>
        <translation>ストローク同士の間隔（モデル単位）</translation>
    </message>
    <message>
        <source>&amp;Angle:</source>
        <translation>角度(&amp;A):</translation>
    </message>
    <message>
        <source>Stroke direction, degrees</source>
        <translation>ストロークの方向（度）</translation>
    </message>
    <message>
        <source>W&amp;idth:</source>
        <translation>太さ(&amp;I):</translation>
    </message>
    <message>
        <source>Stroke width as a fraction of the spacing</source>
        <translation>ストロークの太さ（間隔に対する比率）</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>線</translation>
    </message>
    <message>
        <source>Silhouettes</source>
        <translation>シルエット</translation>
    </message>
    <message>
        <source>Creases</source>
        <translation>折り目</translation>
    </message>
    <message>
        <source>Borders (open edges)</source>
        <translation>境界（開いたエッジ）</translation>
    </message>
    <message>
        <source>Material boundaries</source>
        <translation>マテリアル境界</translation>
    </message>
    <message>
        <source>A crease is drawn where the faces meet at more than this angle</source>
        <translation>隣り合う面がこの角度を超えて折れている箇所に折り目の線を描画します</translation>
    </message>
    <message>
        <source>Crease &amp;angle:</source>
        <translation>折り目の角度(&amp;A):</translation>
    </message>
    <message>
        <source>C&amp;olour:</source>
        <translation>色(&amp;O):</translation>
    </message>
    <message>
        <source>Line colour</source>
        <translation>線の色</translation>
    </message>
    <message>
        <source>O&amp;utline width:</source>
        <translation>輪郭線の太さ(&amp;U):</translation>
    </message>
    <message>
        <source>Silhouettes and borders, pixels</source>
        <translation>シルエットと境界の線の太さ（ピクセル）</translation>
    </message>
    <message>
        <source>&amp;Inner width:</source>
        <translation>内側の線の太さ(&amp;I):</translation>
    </message>
    <message>
        <source>Creases and material boundaries, pixels</source>
        <translation>折り目とマテリアル境界の線の太さ（ピクセル）</translation>
    </message>
    <message>
        <source>&amp;Jitter:</source>
        <translation>ゆらぎ(&amp;J):</translation>
    </message>
    <message>
        <source>Hand-drawn jagged offset, pixels</source>
        <translation>手描き風のギザギザしたずれ（ピクセル）</translation>
    </message>
    <message>
        <source>Width &amp;variation:</source>
        <translation>太さのばらつき(&amp;V):</translation>
    </message>
    <message>
        <source>Relative change of width along strokes</source>
        <translation>ストロークに沿った太さの相対的な変化</translation>
    </message>
    <message>
        <source>O&amp;vershoot:</source>
        <translation>はみ出し(&amp;V):</translation>
    </message>
    <message>
        <source>Extension of stroke ends, pixels</source>
        <translation>ストロークの端を延ばす量（ピクセル）</translation>
    </message>
    <message>
        <source>Stereo</source>
        <translation>ステレオ</translation>
    </message>
    <message>
        <source>Red/cyan anaglyph</source>
        <translation>アナグリフ（赤/シアン）</translation>
    </message>
    <message>
        <source>Dubois red/cyan</source>
        <translation>Dubois（赤/シアン）</translation>
    </message>
    <message>
        <source>Half-colour anaglyph</source>
        <translation>ハーフカラーアナグリフ</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>サイドバイサイド</translation>
    </message>
    <message>
        <source>Top and bottom</source>
        <translation>トップアンドボトム</translation>
    </message>
    <message>
        <source>How the two eyes are combined in the stereo review and stereo renders</source>
        <translation>ステレオレビューとステレオレンダリングで左右の目の画像を合成する方法</translation>
    </message>
    <message>
        <source>&amp;Output:</source>
        <translation>出力(&amp;O):</translation>
    </message>
    <message>
        <source>Distance between the eyes, model units; 0 = automatic (a thirtieth of the convergence distance)</source>
        <translation>左右の目の間の距離（モデル単位）。0 = 自動（輻輳距離の 1/30）</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自動</translation>
    </message>
    <message>
        <source>&amp;Interocular:</source>
        <translation>眼間距離(&amp;I):</translation>
    </message>
    <message>
        <source>Distance of the zero-parallax plane from the camera; 0 = automatic (the model&apos;s centre)</source>
        <translation>カメラから視差ゼロ面までの距離。0 = 自動（モデルの中心）</translation>
    </message>
    <message>
        <source>&amp;Convergence:</source>
        <translation>輻輳距離(&amp;C):</translation>
    </message>
    <message>
        <source>&amp;Toe-in (instead of off-axis)</source>
        <translation>トーイン（オフアクシスの代わりに使用）(&amp;T)</translation>
    </message>
    <message>
        <source>Rotate the eyes towards the convergence point; off-axis (the default) avoids the keystone distortion of toe-in</source>
        <translation>左右の目を輻輳点に向けて回転させます。オフアクシス（既定）では、トーインで生じる台形歪み（キーストーン歪み）が発生しません</translation>
    </message>
    <message>
        <source>S&amp;wap eyes</source>
        <translation>左右の目を入れ替え(&amp;W)</translation>
    </message>
    <message>
        <source>Brightness of this tone (multiplies the base colour)</source>
        <translation>この階調の明るさ（ベースカラーに乗算されます）</translation>
    </message>
    <message>
        <source>from N·L</source>
        <translation>N·L しきい値</translation>
    </message>
    <message>
        <source>The tone starts where N·L + offset reaches this value</source>
        <translation>N·L + オフセットがこの値に達したところからこの階調になります</translation>
    </message>
    <message>
        <source>Brightest:</source>
        <translation>最も明るい階調:</translation>
    </message>
    <message>
        <source>Darkest:</source>
        <translation>最も暗い階調:</translation>
    </message>
    <message>
        <source>Tone %1:</source>
        <translation>階調 %1:</translation>
    </message>
    <message>
        <source>&amp;Dubois Matrices…</source>
        <translation>Dubois 行列(&amp;D)…</translation>
    </message>
    <message>
        <source>The 3 × 3 matrices mapping each eye&apos;s linear RGB to the anaglyph (Dubois least-squares red/cyan by default); tune them to a display and glasses</source>
        <translation>左右それぞれの目のリニア RGB をアナグリフに変換する 3 × 3 行列（既定値は Dubois の最小二乗法による赤/シアン用）。使用するディスプレイとメガネに合わせて調整してください</translation>
    </message>
    <message>
        <source>Dubois Matrices</source>
        <translation>Dubois 行列</translation>
    </message>
    <message>
        <source>Left eye</source>
        <translation>左目</translation>
    </message>
    <message>
        <source>Right eye</source>
        <translation>右目</translation>
    </message>
    <message>
        <source>R out</source>
        <translation>出力 R</translation>
    </message>
    <message>
        <source>G out</source>
        <translation>出力 G</translation>
    </message>
    <message>
        <source>B out</source>
        <translation>出力 B</translation>
    </message>
    <message>
        <source>Silhouettes, creases, borders, material boundaries and apparent ridges</source>
        <translation>シルエット、折り目、境界、マテリアル境界、見かけの稜線</translation>
    </message>
    <message>
        <source>Apparent ridges</source>
        <translation>見かけの稜線</translation>
    </message>
    <message>
        <source>Lines where the surface, as seen from the camera, bends most sharply (Judd et al. 2007): folds and bulges that are neither silhouettes nor creases. Drawn with the inner width; they help depth perception in stereo</source>
        <translation>カメラから見て面が最も急に曲がっているところの線（Judd ほか 2007）: シルエットでも折り目でもない、しわやふくらみです。内側の線の太さで描画され、ステレオでの奥行き知覚を助けます</translation>
    </message>
    <message>
        <source>Apparent ridges are drawn where the view-dependent curvature times the median edge length exceeds this: lower draws more (and noisier) lines, higher only the sharpest folds</source>
        <translation>視点依存の曲率 × エッジ長の中央値がこの値を超えるところに見かけの稜線を描画します。小さくすると線が増え（ノイズも増えます）、大きくすると最も鋭いしわだけを描きます</translation>
    </message>
    <message>
        <source>Ridge &amp;threshold:</source>
        <translation>稜線のしきい値(&amp;T):</translation>
    </message>
    <message>
        <source>Hysteresis: an edge above this angle continues a crease that is already above the crease angle, so creases on a coarse surface do not break into dashes. At or above the crease angle: off</source>
        <translation>ヒステリシス: この角度を超える辺は、すでに折り目の角度を超えている折り目を続けます。粗い面でも折り目が破線に途切れません。折り目の角度以上ではオフです</translation>
    </message>
    <message>
        <source>Crease continues abo&amp;ve:</source>
        <translation>折り目の継続角度(&amp;V):</translation>
    </message>
    <message>
        <source>&amp;Gap joining:</source>
        <translation>隙間の結合(&amp;G):</translation>
    </message>
    <message>
        <source>Stroke ends at most this far apart are joined into one stroke, pixels</source>
        <translation>端どうしがこの距離 (ピクセル) 以内のストロークを 1 本につなぎます</translation>
    </message>
    <message>
        <source>Ta&amp;per:</source>
        <translation>入り抜き(&amp;P):</translation>
    </message>
    <message>
        <source>Length over which strokes thin towards their ends, as a brush lifted off the paper, pixels (0: no taper)</source>
        <translation>筆を紙から離すようにストロークが端に向かって細くなる長さ (ピクセル、0: 入り抜きなし)</translation>
    </message>
    <message>
        <source>&amp;Reduction:</source>
        <translation>距離による減衰(&amp;R):</translation>
    </message>
    <message>
        <source>How much thinner the farthest line is than the nearest, as a fraction of its width (Pencil+&apos;s reduction by distance)</source>
        <translation>最も遠い線が最も近い線よりどれだけ細いか、幅に対する割合 (Pencil+ の距離による減衰)</translation>
    </message>
    <message>
        <source>Rounds of Chaikin smoothing of the projected strokes (corners stay sharp)</source>
        <translation>投影したストロークに Chaikin 平滑化をかける回数 (角は鋭いまま)</translation>
    </message>
    <message>
        <source>S&amp;moothing:</source>
        <translation>平滑化(&amp;M):</translation>
    </message>
    <message>
        <source>Strokes shorter than this, as a percentage of the picture&apos;s height, are dropped</source>
        <translation>画像の高さに対する割合でこれより短いストロークは描きません</translation>
    </message>
    <message>
        <source>Minimum &amp;length:</source>
        <translation>最小の長さ(&amp;L):</translation>
    </message>
    <message>
        <source>Smooth surface</source>
        <translation>滑らかな面</translation>
    </message>
    <message>
        <source>Loop subdivision of the base model: tones and lines are drawn on a smooth surface instead of the facets of a coarse mesh</source>
        <translation>ベースモデルの Loop 細分割: トーンとラインを粗いメッシュの面ではなく滑らかな面に描きます</translation>
    </message>
    <message>
        <source>Subdivision level of renders and of the depth analysis: 0 is the control mesh, each level has four times the triangles of the one before</source>
        <translation>レンダリングと深度解析の細分割レベル: 0 はコントロールメッシュ、各レベルは前のレベルの 4 倍の三角形を持ちます</translation>
    </message>
    <message>
        <source>&amp;Render level:</source>
        <translation>レンダーレベル(&amp;R):</translation>
    </message>
    <message>
        <source>Same as render</source>
        <translation>レンダーと同じ</translation>
    </message>
    <message>
        <source>Subdivision level the viewport shows: the render level by default, so that the viewport shows what renders show; a lower level is faster to draw (never above the render level). Keys 1 and 3 switch between the control mesh and this level</source>
        <translation>ビューポートが表示する細分割レベル: 既定ではレンダーレベルで、ビューポートはレンダリングと同じものを表示します。低いレベルは描画が速くなります（レンダーレベルを超えることはありません）。キー 1 と 3 でコントロールメッシュとこのレベルを切り替えます</translation>
    </message>
    <message>
        <source>&amp;Viewport level:</source>
        <translation>ビューポートレベル(&amp;V):</translation>
    </message>
    <message>
        <source>Join ridges into smooth strokes</source>
        <translation>稜線を滑らかなストロークにつなぐ</translation>
    </message>
    <message>
        <source>Joins the ridge pieces into strokes, smooths them and drops short ones (the thesis&apos;s snakes). Off shows the ridges as extracted, piece by piece</source>
        <translation>稜線の断片をストロークにつなぎ、平滑化して短いものを除きます（論文のスネーク）。オフでは抽出したままの稜線を断片ごとに表示します</translation>
    </message>
    <message>
        <source>Lowers the ridge threshold where the stereo depth error of the picture is high, so that more lines give the eyes something to match there (0: one threshold everywhere). Renders and the depth analysis apply it; the viewport shows the plain threshold</source>
        <translation>画像の立体視の奥行き誤差が大きい所で稜線のしきい値を下げ、線を増やして両眼が対応づける手がかりを与えます（0: どこでも同じしきい値）。レンダーと奥行き解析に適用されます。ビューポートでは通常のしきい値で表示します</translation>
    </message>
    <message>
        <source>Ridges from &amp;depth error:</source>
        <translation>奥行き誤差による稜線(&amp;D):</translation>
    </message>
</context>
<context>
    <name>celform::views::OffsetBrushTool</name>
    <message>
        <source>base layer (every view and frame)</source>
        <translation>ベースレイヤー（すべての視点とフレーム）</translation>
    </message>
    <message>
        <source>key “%1” at frame %2</source>
        <translation>フレーム %2 のキー「%1」</translation>
    </message>
    <message>
        <source>Paint shading offsets into the %1: drag adds, Ctrl+drag subtracts, Shift+drag smooths; F resizes the brush.</source>
        <translation>%1 にシェーディングオフセットを描きます: ドラッグで加算、Ctrl + ドラッグで減算、Shift + ドラッグで平滑化。F でブラシの大きさを変更します。</translation>
    </message>
    <message>
        <source>The mirror finds no twin of this point across the %1 plane: only this side is painted.</source>
        <translation>この点には %1 平面をはさんだミラーの対応点がありません: こちら側だけが塗られます。</translation>
    </message>
</context>
<context>
    <name>celform::views::OutlineSettingsBox</name>
    <message>
        <source>Outline for Fit to Drawing</source>
        <translation>「参照画に合わせる」用の輪郭</translation>
    </message>
    <message>
        <source>A&amp;utomatic</source>
        <translation>自動(&amp;U)</translation>
    </message>
    <message>
        <source>Choose the threshold from the drawing&apos;s histogram (Otsu&apos;s method); off: set it by hand</source>
        <translation>参照画のヒストグラムからしきい値を決めます（大津の手法）。オフ: 手動で設定します</translation>
    </message>
    <message>
        <source>Ink is where the drawing is darker than this (0 black, 1 white); a drawing with transparency uses its alpha instead</source>
        <translation>参照画がこの値より暗い部分をインクとみなします（0 が黒、1 が白）。透明度のある参照画では代わりにアルファを使います</translation>
    </message>
    <message>
        <source>&amp;Threshold:</source>
        <translation>しきい値(&amp;T):</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Radius in drawing pixels that closes gaps in open line art: gaps up to about twice this wide are bridged. 0 closes nothing</source>
        <translation>閉じていない線画のすき間を閉じる半径（参照画のピクセル単位）。この値の約 2 倍までの幅のすき間がつながります。0 では何も閉じません</translation>
    </message>
    <message>
        <source>C&amp;losing radius:</source>
        <translation>クロージング半径(&amp;L):</translation>
    </message>
    <message>
        <source>&amp;Inner lines</source>
        <translation>内側の線(&amp;I)</translation>
    </message>
    <message>
        <source>Keep the shapes the drawing&apos;s inner lines enclose as holes (off: the outer outline alone, the figure filled)</source>
        <translation>参照画の内側の線が囲む形を穴として残します（オフ: 外側の輪郭だけを使い、図形は塗りつぶします）</translation>
    </message>
    <message>
        <source>read from the drawing&apos;s transparency</source>
        <translation>参照画の透明度から読み取り</translation>
    </message>
    <message>
        <source>threshold %1</source>
        <translation>しきい値 %1</translation>
    </message>
    <message numerus="yes">
        <source>Outline found (%1): %n contour(s). O shows it in the viewport.</source>
        <translation>
            <numerusform>輪郭を検出しました（%1）: 輪郭線 %n 本。O キーでビューポートに表示します。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>celform::views::PatchTool</name>
    <message>
        <source>Paint the patch “%1”: drag adds faces, Ctrl+drag removes them, [ and ] change the radius.</source>
        <translation>パッチ「%1」を描きます: ドラッグで面を追加、Ctrl+ドラッグで除去、[ と ] で半径を変更します。</translation>
    </message>
    <message>
        <source>Choose or create a patch in the Highlights dock first.</source>
        <translation>まずハイライトドックでパッチを選ぶか作成してください。</translation>
    </message>
    <message>
        <source>The mirror finds no twin of these faces across the %1 plane: only this side is painted.</source>
        <translation>%1 平面の反対側にこれらの面の相手が見つかりません。こちら側だけを塗ります。</translation>
    </message>
    <message>
        <source>There is not enough memory to analyse the picture.</source>
        <translation>画像を解析するメモリが足りません。</translation>
    </message>
    <message>
        <source>No segment of the depth analysis is under the cursor.</source>
        <translation>カーソルの下に奥行き解析のセグメントがありません。</translation>
    </message>
    <message>
        <source>Segment %1 chosen: click the segment to merge it with.</source>
        <translation>セグメント %1 を選びました: 結合する相手のセグメントをクリックしてください。</translation>
    </message>
    <message>
        <source>Merge Segments</source>
        <translation>セグメントを結合</translation>
    </message>
    <message>
        <source>Segments %1 and %2 merged.</source>
        <translation>セグメント %1 と %2 を結合しました。</translation>
    </message>
    <message>
        <source>The stroke crosses no segment of the depth analysis.</source>
        <translation>ストロークが奥行き解析のどのセグメントも横切っていません。</translation>
    </message>
    <message>
        <source>Split Segment</source>
        <translation>セグメントを分割</translation>
    </message>
    <message>
        <source>Segment %1 split along the stroke.</source>
        <translation>セグメント %1 をストロークに沿って分割しました。</translation>
    </message>
    <message>
        <source>Merge segments: click a segment of the depth analysis, then the one to merge it with.</source>
        <translation>セグメントの結合: 奥行き解析のセグメントをクリックし、次に結合する相手のセグメントをクリックしてください。</translation>
    </message>
    <message>
        <source>Split a segment: drag across a segment of the depth analysis along the cut.</source>
        <translation>セグメントの分割: 奥行き解析のセグメントを横切るように、切り分ける線に沿ってドラッグしてください。</translation>
    </message>
    <message>
        <source>Paint focal points: drag takes the faces towards importance %1 (strength %2), Ctrl+drag back towards 1, [ and ] change the radius.</source>
        <translation>焦点をペイント: ドラッグで面を重要度 %1 に近づけ（強さ %2）、Ctrl+ドラッグで 1 に戻し、[ と ] で半径を変更します。</translation>
    </message>
</context>
<context>
    <name>celform::views::PropertiesPanel</name>
    <message>
        <source>Selection</source>
        <translation>選択</translation>
    </message>
    <message>
        <source>Name shown in the scene tree and used by the command line</source>
        <translation>シーンツリーに表示され、コマンドラインでも使われる名前</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>名前(&amp;N):</translation>
    </message>
    <message>
        <source>Opacity of the drawing over the model in the viewport</source>
        <translation>ビューポートでモデルに重ねて表示する参照画の不透明度</translation>
    </message>
    <message>
        <source>&amp;Opacity:</source>
        <translation>不透明度(&amp;O):</translation>
    </message>
    <message>
        <source>&amp;Enabled in the blend</source>
        <translation>ブレンドに使用(&amp;E)</translation>
    </message>
    <message>
        <source>A disabled key keeps its deformation but takes no part in the blend</source>
        <translation>無効にしたキーは変形を保持したまま、ブレンドには加わりません</translation>
    </message>
    <message>
        <source>View-dependent blend</source>
        <translation>視点依存ブレンド</translation>
    </message>
    <message>
        <source>Sharpness α of the blend weights: 1 blends linearly across the viewing sphere; larger values hold each key longer and switch faster near facet centres.</source>
        <translation>ブレンドウェイトのシャープネス α: 1 では視点球全体で線形にブレンドします。値を大きくするほど各キーが長く保持され、ファセット中心付近で素早く切り替わります。</translation>
    </message>
    <message>
        <source>&amp;Sharpness α:</source>
        <translation>シャープネス α(&amp;S):</translation>
    </message>
    <message>
        <source>Dummy keys (base model)</source>
        <translation>ダミーキー（ベースモデル）</translation>
    </message>
    <message>
        <source>Cosine falloff</source>
        <translation>コサイン減衰</translation>
    </message>
    <message>
        <source>Squared cosine falloff</source>
        <translation>コサイン二乗減衰</translation>
    </message>
    <message>
        <source>How views far from every key are shaped: dummy keys return to the base model along the main axes; cosine modes fade each key out with the angle.</source>
        <translation>どのキーからも遠い視点での形状の決め方です。ダミーキーでは主軸方向に向かってベースモデルに戻り、コサイン系のモードでは角度に応じて各キーがフェードアウトします。</translation>
    </message>
    <message>
        <source>&amp;Unspecified regions:</source>
        <translation>未指定の領域(&amp;U):</translation>
    </message>
    <message>
        <source>Reference drawing</source>
        <translation>参照画</translation>
    </message>
    <message>
        <source>%1 × %2 pixels, %3, %4</source>
        <translation>%1 × %2 ピクセル、%3、%4</translation>
    </message>
    <message>
        <source>camera aligned</source>
        <translation>カメラ位置合わせ済み</translation>
    </message>
    <message>
        <source>camera not aligned yet</source>
        <translation>カメラ未位置合わせ</translation>
    </message>
    <message>
        <source>Key viewpoint</source>
        <translation>キー視点</translation>
    </message>
    <message numerus="yes">
        <source>frame %1: %n vertices moved</source>
        <translation>
            <numerusform>フレーム %1: 頂点 %n 個を移動</numerusform>
        </translation>
    </message>
    <message>
        <source>Direction (%1, %2, %3)
%4</source>
        <translation>方向 (%1, %2, %3)
%4</translation>
    </message>
    <message>
        <source>No deformation yet</source>
        <translation>まだ変形がありません</translation>
    </message>
    <message>
        <source>Base model</source>
        <translation>ベースモデル</translation>
    </message>
    <message>
        <source>%1
%2 vertices, %3 triangles
Size %4 × %5 × %6</source>
        <translation>%1
頂点 %2、三角形 %3
サイズ %4 × %5 × %6</translation>
    </message>
    <message>
        <source>No base model. Import a mesh with File &gt; Import Mesh, or drop a mesh file on the window.</source>
        <translation>ベースモデルがありません。「ファイル」&gt;「メッシュをインポート」でメッシュを読み込むか、メッシュファイルをウィンドウにドロップしてください。</translation>
    </message>
    <message>
        <source>Drawing over the &amp;model</source>
        <translation>参照画をモデルの手前に表示(&amp;M)</translation>
    </message>
    <message>
        <source>Show the drawing over the model (with its opacity) or behind it as a backdrop</source>
        <translation>参照画をモデルの手前に（不透明度を適用して）重ねるか、背景としてモデルの奥に表示します</translation>
    </message>
    <message>
        <source>&amp;Align to Drawing</source>
        <translation>参照画に位置合わせ(&amp;A)</translation>
    </message>
    <message>
        <source>Show the drawing fixed in the viewport and move the camera until the model matches it (Alt+drag orbit/pan/dolly, Alt+Shift+drag roll). The camera is stored with the drawing.</source>
        <translation>参照画をビューポートに固定して表示し、モデルが参照画に重なるまでカメラを動かします（Alt + ドラッグで回転/パン/ドリー、Alt + Shift + ドラッグでロール）。カメラは参照画とともに保存されます。</translation>
    </message>
    <message>
        <source>Vertical field of view of the aligned camera (perspective); a narrower angle is a longer focal length</source>
        <translation>位置合わせしたカメラの垂直画角（透視投影時）。画角が狭いほど焦点距離が長くなります</translation>
    </message>
    <message>
        <source>&amp;Field of view:</source>
        <translation>画角(&amp;F):</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>透視投影</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <translation>平行投影</translation>
    </message>
    <message>
        <source>Projection of the aligned camera</source>
        <translation>位置合わせしたカメラの投影方法</translation>
    </message>
    <message>
        <source>&amp;Projection:</source>
        <translation>投影(&amp;P):</translation>
    </message>
    <message>
        <source>&amp;Match Points</source>
        <translation>点の対応付け(&amp;M)</translation>
    </message>
    <message>
        <source>Click a feature on the model, then Shift+click the same feature on the drawing; repeat for six or more features spread over the model, then Solve Camera</source>
        <translation>モデル上の特徴的な箇所をクリックし、参照画上の同じ箇所を Shift + クリックします。モデル全体に散らばる 6 か所以上で繰り返してから「カメラを推定」を実行します</translation>
    </message>
    <message>
        <source>S&amp;olve Camera</source>
        <translation>カメラを推定(&amp;O)</translation>
    </message>
    <message>
        <source>Find the camera that best projects the model points onto the drawing points</source>
        <translation>モデル上の点を参照画上の点に最もよく一致させて投影するカメラを求めます</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>クリア</translation>
    </message>
    <message>
        <source>Remove every matched point</source>
        <translation>すべての対応点を削除します</translation>
    </message>
    <message>
        <source>Create &amp;Key from Drawing</source>
        <translation>参照画からキーを作成(&amp;K)</translation>
    </message>
    <message>
        <source>Make a key viewpoint in the direction of the drawing&apos;s aligned camera, starting as a copy of the base model</source>
        <translation>参照画に位置合わせしたカメラの方向にキー視点を作成します。初期形状はベースモデルのコピーです</translation>
    </message>
    <message>
        <source>The reference drawing shown while the key is edited</source>
        <translation>キーの編集中に表示する参照画</translation>
    </message>
    <message>
        <source>&amp;Drawing:</source>
        <translation>参照画(&amp;D):</translation>
    </message>
    <message>
        <source>&amp;Edit Key with the Brush</source>
        <translation>ブラシでキーを編集(&amp;E)</translation>
    </message>
    <message>
        <source>Look through the key&apos;s camera with its drawing and deform the key: drag moves in the image plane, Ctrl+drag pushes or pulls along the view, Shift+drag rotates, Ctrl+Shift+drag scales; [ and ] change the radius</source>
        <translation>キーのカメラから参照画とともに表示し、キーを変形します。ドラッグで画像平面内を移動、Ctrl + ドラッグで視線方向に押し/引き、Shift + ドラッグで回転、Ctrl + Shift + ドラッグでスケール。[ と ] で半径を変更します</translation>
    </message>
    <message>
        <source>&amp;Import Deformation…</source>
        <translation>変形をインポート(&amp;I)…</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>ブラシ</translation>
    </message>
    <message>
        <source>Vertices within this distance of the picked vertex (world units) follow it with the falloff (1 − d/r)²; [ and ] in the viewport</source>
        <translation>選択した頂点からこの距離（ワールド単位）以内にある頂点が、減衰 (1 − d/r)² で追従します。ビューポートでは [ と ] で変更できます</translation>
    </message>
    <message>
        <source>&amp;Radius:</source>
        <translation>半径(&amp;R):</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>移動</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>スムーズ</translation>
    </message>
    <message>
        <source>&amp;Mode:</source>
        <translation>モード(&amp;M):</translation>
    </message>
    <message>
        <source>&amp;Preview View-Dependent Shape</source>
        <translation>視点依存形状をプレビュー(&amp;P)</translation>
    </message>
    <message>
        <source>Show the blend of the keys for the viewport&apos;s camera, updated while you orbit (P)</source>
        <translation>ビューポートのカメラに対するキーのブレンド結果を表示します。回転中も更新されます（P）</translation>
    </message>
    <message>
        <source>Solve Camera</source>
        <translation>カメラを推定</translation>
    </message>
    <message>
        <source>Camera solved: the points are %1 drawing pixels off on average. Refine by hand if needed.</source>
        <translation>カメラを推定しました。点のずれは参照画上で平均 %1 ピクセルです。必要に応じて手動で調整してください。</translation>
    </message>
    <message>
        <source>Create Key</source>
        <translation>キーを作成</translation>
    </message>
    <message>
        <source>%1 model points, %2 drawing points: %3 pairs (six or more needed)</source>
        <translation>モデル上の点 %1、参照画上の点 %2: %3 組（6 組以上必要）</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（なし）</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>自然スプライン</translation>
    </message>
    <message>
        <source>Looping cycle</source>
        <translation>ループサイクル</translation>
    </message>
    <message>
        <source>How a key&apos;s deformations at several frames are interpolated between them: a natural cubic spline held before the first and after the last, or a periodic one for looping cycles, whose last keyed frame repeats the first</source>
        <translation>複数フレームにあるキー変形の間の補間方法: 最初より前と最後より後は保持する自然 3 次スプライン、または最後のキーフレームが最初を繰り返すループ用の周期スプライン</translation>
    </message>
    <message>
        <source>&amp;Time:</source>
        <translation>時間(&amp;T):</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>The brush circle&apos;s radius on screen; the world radius follows the zoom at the picked point. [ and ] in the viewport, F to resize by dragging</source>
        <translation>画面上でのブラシの円の半径です。ワールドでの半径は、選んだ点でのズームに従います。ビューポートで [ と ]、F でドラッグして大きさを変えます</translation>
    </message>
    <message>
        <source>World units</source>
        <translation>ワールド単位</translation>
    </message>
    <message>
        <source>Screen pixels</source>
        <translation>画面ピクセル</translation>
    </message>
    <message>
        <source>World: the radius stays the same on the model whatever the zoom. Screen: the circle stays the same on screen (Blender&apos;s View radius)</source>
        <translation>ワールド: ズームにかかわらずモデル上で同じ半径。画面: 画面上で円の大きさが同じ（Blender の「ビュー」半径）</translation>
    </message>
    <message>
        <source>Radius &amp;in:</source>
        <translation>半径の単位(&amp;I):</translation>
    </message>
    <message>
        <source>Paper (1 − d/r)²</source>
        <translation>論文 (1 − d/r)²</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>球</translation>
    </message>
    <message>
        <source>How the pull fades from the picked vertex to the radius. Paper: (1 − d/r)², sharp at the centre. Smooth: flat at the centre, no spikes from small radii. Sphere: a dome</source>
        <translation>選んだ頂点から半径まで、引っ張りがどう弱まるか。論文: (1 − d/r)²、中心が鋭い。スムーズ: 中心が平らで、小さな半径でもとがらない。球: ドーム状</translation>
    </message>
    <message>
        <source>&amp;Falloff:</source>
        <translation>減衰(&amp;F):</translation>
    </message>
    <message>
        <source>Share of the cursor&apos;s motion the picked vertex follows (1: all of it)</source>
        <translation>選んだ頂点がカーソルの動きについて行く割合（1: すべて）</translation>
    </message>
    <message>
        <source>S&amp;trength:</source>
        <translation>強さ(&amp;T):</translation>
    </message>
    <message>
        <source>Last solve: %1 px reprojection error (RMS)</source>
        <translation>前回の解: 再投影誤差 %1 px（RMS）</translation>
    </message>
    <message>
        <source>Match Points: click a feature on the model (pair %1)</source>
        <translation>点の対応付け: モデル上の特徴をクリックしてください（%1 組目）</translation>
    </message>
    <message>
        <source>Match Points: Shift+click the same feature on the drawing (pair %1)</source>
        <translation>点の対応付け: 絵の上で同じ特徴を Shift+クリックしてください（%1 組目）</translation>
    </message>
    <message>
        <source>Relax</source>
        <translation>リラックス</translation>
    </message>
    <message>
        <source>Move drags the selection; Smooth pulls it toward its neighbours while you drag (it flattens spikes); Relax evens the vertices out along the surface and keeps the shape and its silhouette</source>
        <translation>移動は選択部分をドラッグします。スムーズはドラッグ中に隣接頂点の方へ引き寄せます（とがりを平らにします）。リラックスは形とシルエットを保ったまま面に沿って頂点の間隔をそろえます</translation>
    </message>
    <message>
        <source>Apply every stroke to the mirrored side too, across a plane through the model&apos;s centre (X, Y or Z in model space; the detected one is marked), for symmetric characters</source>
        <translation>すべてのストロークをミラー側にも適用します。平面はモデルの中心を通ります（モデル空間の X、Y、Z。検出された平面に印が付きます）。左右対称のキャラクター向けです</translation>
    </message>
    <message>
        <source>M&amp;irror:</source>
        <translation>ミラー(&amp;I):</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>%1 (detected)</source>
        <translation>%1（検出）</translation>
    </message>
    <message>
        <source>Use a mesh made in another tool (same vertex count and order) as this key&apos;s deformation at the playhead&apos;s frame (a new keyed frame, or replacing the one there)</source>
        <translation>他のツールで作ったメッシュ (頂点数と順序が同じもの) を、再生ヘッドのフレームでのこのキーの変形として使います (新しいキーフレーム、またはそこにあるものを置き換え)</translation>
    </message>
</context>
<context>
    <name>celform::views::ScenePanel</name>
    <message>
        <source>Base model</source>
        <translation>ベースモデル</translation>
    </message>
    <message>
        <source>The 3D model that the key deformations change</source>
        <translation>キー変形の対象となる 3D モデル</translation>
    </message>
    <message>
        <source>Base model: %1</source>
        <translation>ベースモデル: %1</translation>
    </message>
    <message>
        <source>Base model: none (File &gt; Import Mesh)</source>
        <translation>ベースモデル: なし（「ファイル」&gt;「メッシュをインポート」）</translation>
    </message>
    <message>
        <source>Reference drawings (%1)</source>
        <translation>参照画 (%1)</translation>
    </message>
    <message>
        <source>The model sheet: hand-drawn views of the character</source>
        <translation>設定画: キャラクターを各方向から手描きした絵</translation>
    </message>
    <message>
        <source>%1 × %2 px, %3%4</source>
        <translation>%1 × %2 px、%3%4</translation>
    </message>
    <message>
        <source>, aligned</source>
        <translation>、位置合わせ済み</translation>
    </message>
    <message>
        <source>, not aligned yet</source>
        <translation>、未位置合わせ</translation>
    </message>
    <message>
        <source>Key viewpoints (%1)</source>
        <translation>キー視点 (%1)</translation>
    </message>
    <message>
        <source>Key deformations, each seen from its key viewpoint</source>
        <translation>キー変形（それぞれのキー視点から見たもの）</translation>
    </message>
    <message>
        <source>Direction (%1, %2, %3)</source>
        <translation>方向 (%1, %2, %3)</translation>
    </message>
    <message>
        <source>The base model, the reference drawings and the key viewpoints of the project.
Double-click or press F2 to rename; Delete removes; the check box disables a key; the eye shows or hides a drawing over the model (D).</source>
        <translation>プロジェクトのベースモデル、参照画、キー視点です。
ダブルクリックまたは F2 で名前を変更、Delete で削除、チェックボックスでキーを無効化、目のアイコンで参照画をモデルの上に表示/非表示します（D）。</translation>
    </message>
    <message>
        <source>Shown over the model: click to hide (D)</source>
        <translation>モデルの上に表示中: クリックで隠す（D）</translation>
    </message>
    <message>
        <source>Hidden: click to show over the model (D)</source>
        <translation>非表示: クリックでモデルの上に表示（D）</translation>
    </message>
</context>
<context>
    <name>celform::views::ShotDepthRunner</name>
    <message>
        <source>Open a model first.</source>
        <translation>まずモデルを開いてください。</translation>
    </message>
    <message>
        <source>the project</source>
        <translation>プロジェクト</translation>
    </message>
    <message>
        <source>Not enough memory to analyse the shot.</source>
        <translation>ショットを解析するためのメモリが足りません。</translation>
    </message>
</context>
<context>
    <name>celform::views::TimelinePanel</name>
    <message>
        <source>Go to the first frame of the range (Shift+Left)</source>
        <translation>範囲の最初のフレームに移動します（Shift+Left）</translation>
    </message>
    <message>
        <source>Go to the previous keyed frame of any kind (Down)</source>
        <translation>種類を問わずキーフレームのある前のフレームに移動します（Down）</translation>
    </message>
    <message>
        <source>Play or pause at the scene&apos;s frame rate (Space)</source>
        <translation>シーンのフレームレートで再生または一時停止します（Space）</translation>
    </message>
    <message>
        <source>Go to the next keyed frame of any kind (Up)</source>
        <translation>種類を問わずキーフレームのある次のフレームに移動します（Up）</translation>
    </message>
    <message>
        <source>Go to the last frame of the range (Shift+Right)</source>
        <translation>範囲の最後のフレームに移動します（Shift+Right）</translation>
    </message>
    <message>
        <source>Loop: after the last frame play the first again</source>
        <translation>ループ: 最後のフレームの後、最初のフレームから再び再生します</translation>
    </message>
    <message>
        <source>The current frame: every view shows the project at this frame</source>
        <translation>現在のフレーム: すべてのビューがこのフレームでのプロジェクトを表示します</translation>
    </message>
    <message>
        <source>First frame of the scene&apos;s range (playback and rendered sequences)</source>
        <translation>シーンの範囲の最初のフレーム（再生と連番レンダー）</translation>
    </message>
    <message>
        <source>Last frame of the scene&apos;s range</source>
        <translation>シーンの範囲の最後のフレーム</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Frames per second of the scene (playback, exports)</source>
        <translation>シーンのフレームレート（再生、エクスポート）</translation>
    </message>
    <message>
        <source>Frames drawn per second while playing; below the scene&apos;s rate, frames are dropped</source>
        <translation>再生中に 1 秒あたりに描画されるフレーム数。シーンのフレームレートを下回るとフレームが間引かれます</translation>
    </message>
    <message>
        <source>Playing: 000.0 fps</source>
        <translation>再生中: 000.0 fps</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>カメラ</translation>
    </message>
    <message>
        <source>deformation</source>
        <translation>変形</translation>
    </message>
    <message>
        <source>highlight</source>
        <translation>ハイライト</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>範囲</translation>
    </message>
    <message>
        <source>Playing…</source>
        <translation>再生中…</translation>
    </message>
    <message>
        <source>Playing: %1 fps</source>
        <translation>再生中: %1 fps</translation>
    </message>
    <message>
        <source>light</source>
        <translation>ライト</translation>
    </message>
    <message>
        <source>Key marks on the ruler, top to bottom: camera keys, light keys, key deformations and highlight keys</source>
        <translation>ルーラー上のキーマーク（上から）: カメラキー、ライトキー、キー変形、ハイライトキー</translation>
    </message>
</context>
<context>
    <name>celform::views::TimelineRuler</name>
    <message>
        <source>camera key</source>
        <translation>カメラのキーフレーム</translation>
    </message>
    <message>
        <source>key deformation</source>
        <translation>キー変形</translation>
    </message>
    <message>
        <source>highlight key</source>
        <translation>ハイライトのキーフレーム</translation>
    </message>
    <message>
        <source>Frame %1</source>
        <translation>フレーム %1</translation>
    </message>
    <message>
        <source>Frame %1: %2</source>
        <translation>フレーム %1: %2</translation>
    </message>
    <message>
        <source>Click or drag to move the current frame</source>
        <translation>クリックまたはドラッグで現在のフレームを移動します</translation>
    </message>
    <message>
        <source>light key</source>
        <translation>ライトキー</translation>
    </message>
    <message>
        <source>▼ camera keys · ■ light keys · ◆ key deformations · ● highlight keys</source>
        <translation>▼ カメラキー · ■ ライトキー · ◆ キー変形 · ● ハイライトキー</translation>
    </message>
</context>
<context>
    <name>celform::views::ViewSpherePanel</name>
    <message>
        <source>Viewing sphere</source>
        <translation>視点球</translation>
    </message>
    <message>
        <source>The key viewpoints on the viewing sphere and their hull. The green facet holds the current view; its red keys are the ones being blended.
Drag to orbit, double-click a key to edit it, double-click empty space to reset the orientation.</source>
        <translation>視点球上のキー視点とその凸包です。緑のファセットに現在の視点があり、そのファセットの赤いキーがブレンドされています。
ドラッグで回転、キーをダブルクリックで編集、何もない場所をダブルクリックで向きをリセットします。</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <comment>key name and its weight</comment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>base %1</source>
        <comment>the base model&apos;s share of the blend</comment>
        <translation>ベース %1</translation>
    </message>
    <message>
        <source> · </source>
        <comment>separator between key weights</comment>
        <translation> · </translation>
    </message>
    <message>
        <source>view · falloff c = %1</source>
        <comment>marker of the current view outside the keys</comment>
        <translation>視点 · 減衰 c = %1</translation>
    </message>
    <message>
        <source>view</source>
        <comment>marker of the current view direction</comment>
        <translation>視点</translation>
    </message>
    <message>
        <source>No base model yet: import a model to build its viewing sphere</source>
        <translation>ベースモデルがまだありません。モデルをインポートすると視点球が作成されます</translation>
    </message>
    <message>
        <source>No keys yet: create a key from an aligned drawing</source>
        <translation>キーがまだありません。位置合わせした参照画からキーを作成してください</translation>
    </message>
    <message>
        <source>All keys are disabled: enable a key to blend it</source>
        <translation>すべてのキーが無効です。ブレンドするにはキーを有効にしてください</translation>
    </message>
    <message>
        <source>The key directions cannot be hulled: the model shows its base shape</source>
        <translation>キーの方向から凸包を作成できません。モデルはベース形状で表示されます</translation>
    </message>
    <message>
        <source>(%1, %2, %3)</source>
        <comment>a direction vector</comment>
        <translation>(%1, %2, %3)</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Direction %2&lt;br&gt;Weight in this view: %3&lt;br&gt;&lt;i&gt;Double-click to edit this key&lt;/i&gt;</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;方向 %2&lt;br&gt;この視点でのウェイト: %3&lt;br&gt;&lt;i&gt;ダブルクリックでこのキーを編集&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dummy key&lt;/b&gt; %1&lt;br&gt;The base model, filling a view no key covers (paper 1, section 3.3)</source>
        <translation>&lt;b&gt;ダミーキー&lt;/b&gt; %1&lt;br&gt;どのキーにも覆われない視点を埋めるベースモデル（論文 1、3.3 節）</translation>
    </message>
    <message>
        <source>&lt;b&gt;Current view&lt;/b&gt;&lt;br&gt;Direction %1</source>
        <translation>&lt;b&gt;現在の視点&lt;/b&gt;&lt;br&gt;方向 %1</translation>
    </message>
</context>
<context>
    <name>celform::views::Viewport</name>
    <message>
        <source>3D viewport</source>
        <translation>3D ビューポート</translation>
    </message>
    <message>
        <source>Brush radius %1</source>
        <translation>ブラシ半径 %1</translation>
    </message>
    <message>
        <source>&lt;p&gt;The 3D view of the model.&lt;/p&gt;&lt;p&gt;Alt+left drag or middle drag: orbit. Alt+middle drag or Shift+middle drag: pan. Alt+right drag, Ctrl+middle drag or the mouse wheel: dolly. F: frame the model. Home: front view.&lt;/p&gt;&lt;p&gt;Ctrl+left drag on the light gizmo (the yellow arrow or sphere): move the key light around the model.&lt;/p&gt;</source>
        <translation>&lt;p&gt;モデルの 3D ビューです。&lt;/p&gt;&lt;p&gt;Alt + 左ボタンドラッグまたは中ボタンドラッグ: 回転（オービット）。Alt + 中ボタンドラッグまたは Shift + 中ボタンドラッグ: パン。Alt + 右ボタンドラッグ、Ctrl + 中ボタンドラッグ、またはマウスホイール: ドリー。F: モデル全体を表示。Home: 正面ビュー。&lt;/p&gt;&lt;p&gt;ライトのギズモ（黄色の矢印または球）上で Ctrl + 左ボタンドラッグ: モデルの周りでキーライトを移動。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Brush radius %1 px</source>
        <translation>ブラシ半径 %1 px</translation>
    </message>
    <message>
        <source>Frame all</source>
        <translation>全体を表示</translation>
    </message>
    <message>
        <source>Front view, framed</source>
        <translation>正面から全体を表示</translation>
    </message>
    <message>
        <source>Brush radius smaller (× 0.8)</source>
        <translation>ブラシの半径を小さく（× 0.8）</translation>
    </message>
    <message>
        <source>Brush radius larger (× 1.25)</source>
        <translation>ブラシの半径を大きく（× 1.25）</translation>
    </message>
    <message>
        <source>Resize the brush with the mouse (click or Enter keeps, Esc cancels)</source>
        <translation>マウスでブラシのサイズを変更（クリックか Enter で確定、Esc で取り消し）</translation>
    </message>
    <message>
        <source>%1 would take the view off the camera being edited; leave the tool first (Esc).</source>
        <translation>%1 を行うと編集中のカメラから視点が外れます。先にツールを終了してください (Esc)。</translation>
    </message>
    <message>
        <source>Frame All</source>
        <translation>全体を表示</translation>
    </message>
    <message>
        <source>A preset view</source>
        <translation>プリセットの視点</translation>
    </message>
    <message>
        <source>The front view</source>
        <translation>正面の視点</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>only one project can be opened</source>
        <translation>開けるプロジェクトは 1 つだけです</translation>
    </message>
</context>
</TS>
