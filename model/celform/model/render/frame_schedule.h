// Handing a render job's frames to several threads (renderFrames, render_job.h): which frame each
// thread takes next, frames skipped because their file exists, progress and listener one at a time, and
// the failure reported once every thread has stopped.
#pragma once

#include "celform/model/render/render_job.h"

#include <QString>

#include <functional>

namespace celform::model {

/// Writes a rendered frame's file. It runs on the job's writer thread while the thread that
/// rendered the frame goes on with its next one (issue 29: encoding and writing overlap rendering,
/// even with one render thread). Failures are thrown (IoError naming the file, bad_alloc).
using FrameWrite = std::function<void()>;

/// Renders one frame and returns how to write its file. It may keep buffers and caches between its
/// calls, as long as the file it writes for a frame does not depend on the frames it rendered
/// before. At most one of its writes runs at a time, and a call starts only once the write before
/// the previous one has finished: the data of two frames' writes (used in turn) is all it keeps
/// apart from its passes. cancelled() is asked between the render and making the write: when it
/// says stop, the renderer returns an empty FrameWrite. Failures are thrown as FrameWrite's.
using FrameRenderer = std::function<FrameWrite(int frame, const QString& file, const std::function<bool()>& cancelled)>;

/// Runs the job's frames, in order of frame, on min(job.threads, frame count) threads (the
/// calling thread is one of them), each with a renderer of its own made by makeRenderer on that
/// thread before its first frame, and one writer thread besides them that writes the files in the
/// order they were rendered. A frame counts as done (listener, progress) once its file is written;
/// the progress is asked again before each write, and a frame rendered but not yet written when it
/// says stop is dropped. With job.skipExisting a frame whose file exists (a regular file, or a
/// link to one) and holds a whole image (incompleteImageProblem) is reported to listener as skipped
/// and not rendered. After a failure no new frame starts; the frames under way before the failed
/// one are finished and written, later ones are dropped. Returns how many files were written;
/// throws RenderFrameError for the lowest frame that failed.
int scheduleFrames(const RenderJob& job, algo::Progress* progress, RenderFrameListener* listener,
    const std::function<FrameRenderer()>& makeRenderer);

/// What one thread's stack and its malloc arena take from the address space (8 MB and 64 MB),
/// counted with every frame's buffers where an address-space limit (ulimit -v) is set.
constexpr qint64 kRenderThreadOverheadBytes = qint64(72) << 20;

/// How many of a job's frames fit in memory at once: job.threads, fewer when that many frames'
/// buffers (RenderJob::bytesNeeded, plus kRenderThreadOverheadBytes each) would need more than
/// availableBytes (availableRenderMemory()), and never more than the job's frames; at least 1.
int concurrentFrames(const RenderJob& job, qint64 availableBytes);

} // namespace celform::model
