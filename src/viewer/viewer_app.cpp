#include "viewer/viewer_app.h"

#include "core/error.h"
#include "core/interruption.h"
#include "core/log.h"
#include "gl/gpu_timer.h"
#include "viewer/frame_images.h"
#include "viewer/glfw_window.h"
#include "viewer/imgui_layer.h"
#include "viewer/path_recorder.h"
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
#include <optional>

namespace glint::viewer {
namespace {

using Clock = std::chrono::steady_clock;

class ViewerApp {
public:
  explicit ViewerApp(const ViewerLaunch& launch)
      : window_("glint view: " + launch.options.scene,
                launch.options.width + 2 * static_cast<int>(kPanelWidth), std::max(launch.options.height, 720)),
        ui_(window_),
        session_(launch.options, pass_timing_for_renderer(window_.renderer())),
        script_path_(launch.script) {
    state_.options = launch.options;
    if (launch.frame >= session_.frame_count())
      fail("--frame {} is past the walkthrough's last frame, {}", launch.frame, session_.frame_count() - 1);
    state_.frame = launch.frame;
    // On a software renderer a frame takes long: render when something changes only.
    state_.continuous = pass_timing_for_renderer(window_.renderer()) == PassTimingMethod::gpu_queries;
    if (!launch.script.empty()) script_ = load_viewer_script(launch.script, session_.frame_count(), launch.options);
    backends_ = available_backends();
    log_info("view: {} on {}", launch.options.scene, window_.renderer());
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
      if (state_.continuous || state_.playing || state_.flying) window_.poll_events();
      else window_.wait_events(0.05);
      if (window_.close_requested()) return 0;
      const Clock::time_point now = Clock::now();
      const float seconds = std::chrono::duration<float>(now - last).count();
      last = now;
      if (run_script(now)) return 0;

      ViewerRequests requests;
      ui_.begin_frame();
      input_.update(window_.handle(), seconds, window_.take_scroll(), ui_.wants_mouse(), ui_.wants_keyboard(), state_,
                    requests);
      draw_panels(panel_context(), state_, requests);
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
      show_picture();
      ui_.end_frame(kPanelWidth);
      window_.swap_buffers();
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
        state_.flying = true;
        state_.playing = false;
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
    context.frame_count = session_.frame_count();
    context.renderer = window_.renderer();
    context.backends = backends_;
    context.recording = recorder_.recording();
    context.recorded_points = recorder_.size();
    context.difference = images_.difference ? &*images_.difference : nullptr;
    context.stats = &stats_;
    return context;
  }

  void handle(const ViewerRequests& requests) {
    if (requests.start_flying && !state_.flying) {
      state_.fly = FlyCamera(session_.walkthrough_state(current_frame()).camera);
      state_.flying = true;
    }
    if (requests.back_to_path) state_.flying = false;
    if (requests.reload) reload();
    if (requests.record_toggle) recorder_.recording() ? recorder_.stop() : recorder_.start();
    if (requests.record_save) save_path(state_.record_path);
  }

  void reload() {
    session_.reload_scene();
    state_.frame = std::min(state_.frame, static_cast<double>(session_.frame_count() - 1));
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

  // Playback: the walkthrough's frame rate times the speed; flying pauses it (each new frame of a
  // flown view rebuilds the loop, see viewer_session.h).
  void advance(float seconds) {
    if (!state_.playing || state_.flying) return;
    const double fps = static_cast<double>(session_.rest_scene().walkthrough.frames_per_second);
    state_.frame += static_cast<double>(seconds) * fps * static_cast<double>(state_.speed);
    state_.frame = std::fmod(state_.frame, static_cast<double>(session_.frame_count()));
  }

  int current_frame() const { return std::clamp(static_cast<int>(state_.frame), 0, session_.frame_count() - 1); }

  ViewPoint view_point() const {
    ViewPoint view{current_frame(), std::nullopt};
    if (state_.flying) view.camera = state_.fly.state(session_.rest_scene().walkthrough.camera.fov_y_degrees);
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
      session_.set_options(scaled_options());
    } catch (const Error&) {
      if (!strict) adopt_session_options();
      throw;
    }
    if (state_.light_stays != session_.fixed_light().has_value())
      session_.set_fixed_light(state_.light_stays
                                   ? std::optional<vec3>(session_.walkthrough_state(current_frame()).light_position)
                                   : std::nullopt);
  }

  // The panels show the settings the session renders with (its size is the scaled one).
  void adopt_session_options() {
    const int width = state_.options.width, height = state_.options.height;
    state_.options = session_.options();
    state_.options.width = width;
    state_.options.height = height;
  }

  void render_if_needed(bool strict) {
    apply_state(strict);
    const ViewPoint view = view_point();
    const bool changed = !rendered_ || !(rendered_->view == view) ||
                         !same_viewer_settings(rendered_->options, session_.options()) ||
                         rendered_->light != session_.fixed_light();
    if (changed || (state_.continuous && !strict)) {
      FrameMeasurement measured = session_.render(view);
      const Clock::time_point now = Clock::now();
      stats_.add(measured, last_render_ ? std::chrono::duration<double, std::milli>(now - *last_render_).count() : 0.0);
      last_render_ = now;
      // A re-render of the same view (render continuously) keeps its difference: the reference
      // builds a loop of its own, too slow to make every frame.
      std::optional<DifferenceFromRt> difference;
      if (!changed) difference = std::move(images_.difference);
      images_ = FrameImages{std::move(*measured.final_image), {}, std::move(difference)};
      rendered_ = Rendered{view, session_.options(), session_.fixed_light()};
      views_read_ = false;
      if (state_.flying) recorder_.sample(*view.camera);
    }
    // The pictures the chosen view needs, read from the pipeline that still holds the frame.
    if (state_.view != "final" && state_.view != "difference") read_views();
    if (state_.view == "difference" && !images_.difference)
      images_.difference = difference_from_reference(images_.final_image, session_.render_reference(view));
  }

  void read_views() {
    if (views_read_) return;
    images_.views = session_.debug_views();
    views_read_ = true;
  }

  void screenshot(const std::string& path) {
    if (!rendered_) render_if_needed(true);
    read_views();
    const std::vector<std::filesystem::path> written = write_screenshot(path, images_);
    state_.status = fmt::format("wrote {} and {} view{}", path, written.size() - 1, written.size() == 2 ? "" : "s");
    log_info("view: {}", state_.status);
  }

  void show_picture() {
    if (!rendered_) return;
    const ImageRgba8* picture = images_.find(state_.view);
    ui_.show(picture != nullptr ? *picture : images_.final_image);
  }

  struct Rendered {
    ViewPoint view;
    RenderOptions options;
    std::optional<vec3> light;
  };

  GlfwWindow window_;
  ImGuiLayer ui_;
  ViewerSession session_;
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
  std::optional<Clock::time_point> last_render_;
};

}  // namespace

int run_viewer(const ViewerLaunch& launch) {
  ViewerApp app(launch);
  return app.run();
}

}  // namespace glint::viewer
