"use strict";
// The run's video tied to the timeline: seeking the timeline seeks the video (a second of video
// shows `rate` simulated seconds), and playing or seeking the video moves the timeline. A live run's
// video is shown once the run has ended and its world has written it (an MP4 plays only once whole).

const clip_ = { rate: 1, set: null };

function showVideo(video) {
  if (!video || $("video").getAttribute("src")) return;
  clip_.rate = video.rate;
  $("video").src = video.src;
  $("video-box").hidden = false;
}

// The timeline moved: the video shows the frame of that time (unless it is what moved it).
function videoFollows(time) {
  const v = $("video");
  if (!v.getAttribute("src") || v.readyState < 1 || !v.paused) return;
  const at = Math.min(time / clip_.rate, v.duration || 0);
  if (Math.abs(v.currentTime - at) < 1e-3) return;
  clip_.set = at;
  v.currentTime = at;
}

function timelineFollows() {
  const v = $("video");
  const time = v.currentTime * clip_.rate;
  if (Math.abs(time - page.time) < 1e-6) return;
  $("follow").checked = false;
  window.hfsm.seek(time);
}

function setUpVideo() {
  const v = $("video");
  v.addEventListener("seeked", () => {
    if (clip_.set !== null && Math.abs(v.currentTime - clip_.set) < 1e-3) { clip_.set = null; return; }
    timelineFollows();  // the person moved the video
  });
  v.addEventListener("timeupdate", () => { if (!v.paused) timelineFollows(); });
  v.addEventListener("pause", timelineFollows);  // stopped, or at its end: the last frame's time
  v.addEventListener("play", () => { if (page.playing) $("play").click(); });
  v.addEventListener("loadedmetadata", () => videoFollows(page.time));
}

// A live run has ended: ask for its video while the world is writing it (not when it writes none,
// nor once the server has gone).
function awaitVideo() {
  const ask = async () => {
    let meta;
    try { meta = await (await fetch("/api/meta")).json(); } catch (e) { return; }
    if (meta.video) showVideo(meta.video);
    else if (meta.video_pending) setTimeout(ask, 500);
  };
  ask();
}
