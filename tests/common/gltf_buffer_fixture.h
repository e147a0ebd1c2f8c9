// The glTF file of the tests that readers open only regular files, shared by the mesh
// import (Assimp) and the animated base import (tinygltf) tests.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <sys/stat.h> // mkfifo

namespace celform::test {

/// The rows: a buffer uri naming a FIFO, a device, a folder (made by makeBufferTargets()).
inline void addBufferUriRows()
{
    QTest::addColumn<QString>("uri");
    QTest::newRow("fifo") << "pipe.bin";
    QTest::newRow("device") << "/dev/zero";
    QTest::newRow("folder") << "folder";
}

/// Makes pipe.bin (a FIFO) and folder/ in dir; false when either cannot be made.
inline bool makeBufferTargets(const QTemporaryDir& dir)
{
    return ::mkfifo(QFile::encodeName(dir.filePath(QStringLiteral("pipe.bin"))).constData(), 0600) == 0
        && QDir(dir.path()).mkdir(QStringLiteral("folder"));
}

/// One triangle's positions in a 4 GB buffer read from uri: opening a FIFO would block for ever,
/// /dev/zero would be read without end.
inline QByteArray gltfWithBufferUri(const QString& uri)
{
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],
      "buffers":[{"byteLength":4000000000,"uri":")"
        + uri.toUtf8() + R"("}]})";
}

} // namespace celform::test
