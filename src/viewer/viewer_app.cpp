#include "viewer/viewer_app.h"

#include "core/error.h"
#include "core/interruption.h"
#include "core/log.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "viewer/frame_images.h"
#include "viewer/glfw_window.h"
#include "viewer/imgui_layer.h"
#include "viewer/path_recorder.h"
#include "viewer/playback.h"
#include "viewer/stats_history.h"
#include "viewer/viewer_input.h"
#include "viewer/viewer_panels.h"
#include "viewer/viewer_script.h"
#include "viewer/viewer_session.h"
#include "viewer/viewer_settings.h"
#include "viewer/viewer_state.h"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace glint::viewer {
namespace {

using Clock = std::chrono::steady_clock;

class ViewerApp {
public:
  explicit ViewerApp(const ViewerLaunch& launch) : script_path_(launch.script) {
    if (launch.offscreen && launch.script.empty()) fail("view: --offscreen needs a --script to run (there is no window)");
    // A script runs offscreen when asked, or when there is no display to open a window on.
    std::optional<std::string> no_display;
    if (!launch.offscreen) no_display = GlfwWindow::why_no_display();
    if (launch.offscreen || (no_display && !launch.script.empty())) {
      offscreen_ = std::make_unique<HeadlessGlContext>();
      renderer_ = offscreen_->renderer();
    } else {
      window_ = std::make_unique<GlfwWindow>("glint view: " + launch.options.scene,
                                             launch.options.width + 2 * static_cast<int>(kPanelWidth),
                                             std::max(launch.options.height, 720));
      ui_ = std::make_unique<ImGuiLayer>(*window_);
      renderer_ = window_->renderer();
    }
    session_ = std::make_unique<ViewerSession>(launch.options, pass_timing_for_renderer(renderer_));
    state_.options = launch.options;
    if (launch.frame >= session_->frame_count())
      fail("--frame {} is past the walkthrough's last frame, {}", launch.frame, session_->frame_count() - 1);
    state_.frame = launch.frame;
    // On a software renderer a frame takes long: render when something changes only.
    state_.continuous = pass_timing_for_renderer(renderer_) == PassTimingMethod::gpu_queries;
    if (!launch.script.empty()) script_ = load_viewer_script(launch.script, session_->frame_count(), launch.options);
    if (offscreen_ && (script_.empty() || script_.back().verb != ScriptVerb::quit)) {
      // Without `quit` the script leaves the window open for a person: it needs one.
      if (no_display) fail("{}", *no_display);
      fail("{}: --offscreen runs the script to its end, which must be `quit` (there is no window to leave open)",
           launch.script.string());
    }
    backends_ = available_backends();
    log_info("view: {} on {}{}", launch.options.scene, renderer_, offscreen_ ? ", offscreen (no window)" : "");
  }

  int run() {
    const InterruptionScope interruptible;
    Clock::time_point last = Clock::now();
    while (true) {
      if (interruption_requested()) {
        log_warning("view: interrupted by {}", interruption_signal_name());
        return interrupted_exit_code();
      }
      // Nothing moves on its own: wait for input (a twentieth of a second at most, so that signals
      // and the script's waits are still seen) instead of redrawing the panels as fast as possible.
      const bool idle = !state_.continuous && !state_.playing && !state_.flying;
      if (window_) {
        if (idle) window_->wait_events(0.05);
        else window_->poll_events();
        if (window_->close_requested()) return 0;
      } else if (idle && now_waiting()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      const Clock::time_point now = Clock::now();
      const float seconds = std::chrono::duration<float>(now - last).count();
      last = now;
      if (run_script(now)) return 0;

      ViewerRequests requests;
      if (ui_) {
        ui_->begin_frame();
        input_.update(window_->handle(), seconds, window_->take_scroll(), ui_->wants_mouse(), ui_->wants_keyboard(),
                      state_, requests);
        draw_panels(panel_context(), state_, requests);
      }
      try {
        handle(requests);
        advance(seconds);
        render_if_needed(false);
        if (requests.screenshot) screenshot(state_.screenshot_path);
      } catch (const Error& error) {
        state_.status = error.what();  // shown in the View panel; the viewer goes on
        log_warning("view: {}", error.what());
        adopt_session_options();  // a loop that failed to build went back to the settings before
      }
      if (ui_) {
        show_picture();
        ui_->end_frame(kPanelWidth);
        window_->swap_buffers();
      }
    }
  }

private:
  // Runs the script's commands due now; true after `quit`. A failing command is one error naming its line.
  bool run_script(Clock::time_point now) {
    while (next_command_ < script_.size() && now >= wait_until_) {
      const ScriptCommand& command = script_[next_command_++];
      try {
        if (command.verb == ScriptVerb::quit) return true;
        execute(command);
      } catch (const Error& error) {
        fail("{}:{}: {}", script_path_.string(), command.line, error.what());
      }
      if (command.verb == ScriptVerb::wait) break;
    }
    return false;
  }

  // Whether the script is in a `wait` (offscreen, an idle viewer then sleeps instead of spinning).
  bool now_waiting() const { return Clock::now() < wait_until_; }

  void execute(const ScriptCommand& command) {
    const std::vector<std::string>& a = command.arguments;
    switch (command.verb) {
      case ScriptVerb::set:
        if (a[0] == "scale") state_.scale = std::stof(a[1]);
        else if (a[0] == "speed") state_.speed = std::stof(a[1]);
        else if (a[0] == "light") state_.light_stays = a[1] == "stay";
        else if (a[0] == "view") state_.view = a[1];
        else set_viewer_setting(state_.options, a[0], a[1]);
        apply_state(/*strict=*/true);
        return;
      case ScriptVerb::frame:
        state_.frame = std::stod(a[0]);
        state_.playing = false;
        return;
      case ScriptVerb::play: state_.playing = true; return;
      case ScriptVerb::pause: state_.playing = false; return;
      case ScriptVerb::camera: {
        CameraState camera;
        camera.position = script_point("camera", a[0]);
        camera.target = script_point("target", a[1]);
        state_.fly = FlyCamera(camera);
        state_.flying = true;  // playing goes on: the flown camera sees the frames as they play
        return;
      }
      case ScriptVerb::path: state_.flying = false; return;
      case ScriptVerb::wait: wait_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                                std::chrono::duration<double>(std::stod(a[0])));
        return;
      case ScriptVerb::screenshot:
        apply_state(/*strict=*/true);
        render_if_needed(/*strict=*/true);
        screenshot(a[0]);
        return;
      case ScriptVerb::record:
        if (a[0] == "start") recorder_.start();
        else if (a[0] == "stop") recorder_.stop();
        else save_path(a[0].substr(5));
        return;
      case ScriptVerb::reload: reload(); return;
      case ScriptVerb::quit: return;
    }
  }

  PanelContext panel_context() const {
    PanelContext context;
    context.frame_count = session_->frame_count();
    context.renderer = renderer_;
    context.backends = backends_;
    context.recording = recorder_.recording();
    context.recorded_points = recorder_.size();
    context.difference = images_.difference ? &*images_.difference : nullptr;
    context.stats = &stats_;
    return context;
  }

  void handle(const ViewerRequests& requests) {
    if (requests.start_flying && !state_.flying) {
      state_.fly = FlyCamera(session_->walkthrough_state(current_frame()).camera);
      state_.flying = true;
    }
    if (requests.back_to_path) state_.flying = false;
    if (requests.reload) reload();
    if (requests.record_toggle) recorder_.recording() ? recorder_.stop() : recorder_.start();
    if (requests.record_save) save_path(state_.record_path);
  }

  void reload() {
    session_->reload_scene();
    state_.frame = std::min(state_.frame, static_cast<double>(session_->frame_count() - 1));
    rendered_.reset();
    state_.status = "reloaded " + state_.options.scene;
  }

  void save_path(const std::string& requested) {
    const std::filesystem::path scene(state_.options.scene);
    std::filesystem::path out = requested;
    if (out.empty()) {
      std::string name = scene.filename().string();
      name = name.substr(0, name.size() - std::min(name.size(), std::string(".scene.json").size()));
      out = scene.parent_path() / (name + ".recorded.scene.json");
    }
    recorder_.save(scene, out);
    state_.status = fmt::format("wrote {} camera points to {}", recorder_.size(), out.string());
  }

  void advance(float seconds) {
    advance_playback(state_, seconds, static_cast<float>(session_->rest_scene().walkthrough.frames_per_second),
                     session_->frame_count());
  }

  int current_frame() const { return std::clamp(static_cast<int>(state_.frame), 0, session_->frame_count() - 1); }

  ViewPoint view_point() const {
    ViewPoint view{current_frame(), std::nullopt};
    if (state_.flying) view.camera = state_.fly.state(session_->rest_scene().walkthrough.camera.fov_y_degrees);
    return view;
  }

  RenderOptions scaled_options() const {
    RenderOptions options = state_.options;
    options.width = std::max(16, static_cast<int>(std::lround(static_cast<float>(options.width) * state_.scale)));
    options.height = std::max(16, static_cast<int>(std::lround(static_cast<float>(options.height) * state_.scale)));
    return options;
  }

  // Hands the settings and the light to the session. A setting this machine cannot run is refused:
  // strict (the script) throws, otherwise the panels go back to the settings in use.
  void apply_state(bool strict) {
    try {
      session_->set_options(scaled_options());
    } catch (const Error&) {
      if (!strict) adopt_session_options();
      throw;
    }
    if (state_.light_stays != session_->fixed_light().has_value())
      session_->set_fixed_light(state_.light_stays
                                   ? std::optional<vec3>(session_->walkthrough_state(current_frame()).light_position)
                                   : std::nullopt);
  }

  // The panels show the settings the session renders with (its size is the scaled one).
  void adopt_session_options() {
    const int width = state_.options.width, height = state_.options.height;
    state_.options = session_->options();
    state_.options.width = width;
    state_.options.height = height;
  }

  void render_if_needed(bool strict) {
    apply_state(strict);
    const ViewPoint view = view_point();
    const bool changed = !rendered_ || !(rendered_->view == view) ||
                         !same_viewer_settings(rendered_->options, session_->options()) ||
                         rendered_->light != session_->fixed_light();
    if (changed || (state_.continuous && !strict)) {
      FrameMeasurement measured = session_->render(view);
      const Clock::time_point now = Clock::now();
      stats_.add(measured, last_render_ ? std::chrono::duration<double, std::milli>(now - *last_render_).count() : 0.0);
      last_render_ = now;
      // A re-render of the same view (render continuously) keeps its difference: the reference
      // builds a loop of its own, too slow to make every frame.
      std::optional<DifferenceFromRt> difference;
      if (!changed) difference = std::move(images_.difference);
      images_ = FrameImages{std::nullopt, {}, std::move(difference)};
      rendered_ = Rendered{view, session_->options(), session_->fixed_light()};
      ++renders_;
      views_read_ = false;
      if (state_.flying) recorder_.sample(*view.camera);
    }
    // The pictures the chosen view needs, read from the pipeline that still holds the frame.
    if (state_.view != "final" && state_.view != "difference") read_views();
    if (state_.view == "difference" && !images_.difference)
      images_.difference = difference_from_reference(final_image(), session_->render_reference(view));
  }

  // The final image on the host, read from the pipeline once per render (screenshots, the difference).
  const ImageRgba8& final_image() {
    if (!images_.final_image) images_.final_image = session_->final_image();
    return *images_.final_image;
  }

  void read_views() {
    if (views_read_) return;
    images_.views = session_->debug_views();
    views_read_ = true;
  }

  void screenshot(const std::string& path) {
    if (!rendered_) render_if_needed(true);
    (void)final_image();
    read_views();
    const std::vector<std::filesystem::path> written = write_screenshot(path, images_);
    state_.status = fmt::format("wrote {} and {} view{}", path, written.size() - 1, written.size() == 2 ? "" : "s");
    log_info("view: {}", state_.status);
  }

  // The final image goes from the pipeline's texture to the picture's on the GPU; other views are
  // host images (debug views, the heat map) and are uploaded. Either only when it changed.
  void show_picture() {
    if (!rendered_) return;
    const ImageRgba8* picture = state_.view == "final" ? nullptr : images_.find(state_.view);
    const Shown shown{renders_, picture != nullptr ? state_.view : "final"};
    if (shown_ == shown) return;
    if (picture != nullptr) {
      ui_->picture().upload(*picture);
    } else {
      if (session_->final_texture() == 0) return;  // the loop failed to rebuild: keep the last picture
      ui_->picture().copy_from(session_->final_texture(), session_->rendered_width(), session_->rendered_height());
    }
    shown_ = shown;
  }

  struct Shown {
    std::uint64_t render = 0;
    std::string view;
    bool operator==(const Shown&) const = default;
  };

  struct Rendered {
    ViewPoint view;
    RenderOptions options;
    std::optional<vec3> light;
  };

  // One of the two GL contexts: the window's, or (a script offscreen) a headless EGL one. Declared
  // before the session so that its GL objects go first.
  std::unique_ptr<HeadlessGlContext> offscreen_;
  std::unique_ptr<GlfwWindow> window_;
  std::unique_ptr<ImGuiLayer> ui_;
  std::string renderer_;  // GL_RENDERER of the context in use
  std::unique_ptr<ViewerSession> session_;
  std::filesystem::path script_path_;
  std::vector<ScriptCommand> script_;
  std::size_t next_command_ = 0;
  Clock::time_point wait_until_{};
  ViewerState state_;
  ViewerInput input_;
  StatsHistory stats_;
  PathRecorder recorder_;
  std::vector<std::string> backends_;
  FrameImages images_;
  bool views_read_ = false;
  std::optional<Rendered> rendered_;
  std::uint64_t renders_ = 0;   // renders so far: which one the picture shows
  std::optional<Shown> shown_;  // what the picture texture holds
  std::optional<Clock::time_point> last_render_;
};

}  // namespace

int run_viewer(const ViewerLaunch& launch) {
  ViewerApp app(launch);
  return app.run();
}

}  // namespace glint::viewer
