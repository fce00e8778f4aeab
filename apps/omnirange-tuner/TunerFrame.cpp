#include "TunerFrame.h"

#include <omnirange/train/BirdsEyeView.h>

#include <mrpt/gui/WxUtils.h>
#include <mrpt/img/CImage.h>

#include <opencv2/imgproc.hpp>

#include <omnirange_apps/CommandLine.h>

#include <omnirange/config/OptionsTable.h>
#include <omnirange/config/Output.h>

#include <wx/button.h>
#include <wx/display.h>
#include <wx/scrolwin.h>
#include <wx/msgdlg.h>
#include <wx/progdlg.h>
#include <wx/sizer.h>
#include <wx/wrapsizer.h>
#include <wx/dcclient.h>
#include <wx/statusbr.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

using namespace omnirange;

namespace
{
constexpr int kPlotSize = 300, kSmall = 146;
constexpr int kControlsWidth = 390;  // the right-hand column, scrolled when the window is short
constexpr int kMinImageWidth = 320, kMaxImageWidth = 1024;
constexpr int kErrorPlotHeight = 64;
constexpr int kGrab = 8;  // [display px] how near a circle or the arrow's tip a press takes it

wxBitmap toBitmap(const cv::Mat& bgr, int width)
{
	cv::Mat shown = bgr;
	if (bgr.cols != width)
		cv::resize(bgr, shown, cv::Size(width, bgr.rows * width / bgr.cols), 0, 0, cv::INTER_AREA);
	const std::unique_ptr<wxBitmap> b(mrpt::gui::MRPTImage2wxBitmap(mrpt::img::CImage(shown, mrpt::img::DEEP_COPY)));
	return *b;
}

/** "N [px]": a key and its unit, as a control's label. */
std::string labelOf(const FieldInfo& f)
{
	return f.unit == "-" || f.unit == "bool" ? f.key : f.key + " [" + f.unit + "]";
}

/** The key's meaning and range, as its tooltip (the table's text, as in the docs). */
wxString tooltipOf(const FieldInfo& f)
{
	std::string tip = f.doc;
	if (f.range) tip += " (" + f.range->text() + ")";
	if (!f.choices.empty())
	{
		tip += " (";
		for (std::size_t i = 0; i < f.choices.size(); ++i) tip += (i ? ", " : "") + f.choices[i];
		tip += ")";
	}
	return wxString::FromUTF8(tip);
}

/** The text a control shows for its key: typed text not yet committed (no
 * Enter, focus not left) counts, as it is what the user sees. */
template <class KeyControl>
std::string shownText(const KeyControl& c)
{
	if (c.number) return trimmed(c.number->GetTextValue().ToStdString());
	if (c.choice) return c.choice->GetStringSelection().ToStdString();
	return c.check->GetValue() ? "true" : "false";
}
}  // namespace

int TunerFrame::imageWidthFor(const wxSize& client)
{
	// 4:3 image; below it the frame's buttons, the overlays' switches, the actions
	// and the keys (about 170 px), and the status bar.
	const int by_height = (client.GetHeight() - 200) * 4 / 3,
			  by_width = client.GetWidth() - kPlotSize - kControlsWidth - 24;
	return std::clamp(std::min(by_height, by_width), kMinImageWidth, kMaxImageWidth);
}

template <class Event, class Handler>
void TunerFrame::bindGuarded(wxEvtHandler* source, const wxEventTypeTag<Event>& type, Handler handler)
{
	source->Bind(type, [this, handler](Event& e) {
		try
		{
			handler(e);
		}
		catch (const std::exception& ex)
		{
			status(wxString::FromUTF8(omnirange::app::errorText(ex)), Say::Error);
		}
	});
}

TunerFrame::TunerFrame(tuner::TunerSession& session, std::string save_to, int first_frame)
	: wxFrame(nullptr, wxID_ANY, "omnirange-tuner: " + session.options().rawlog),
	  s_(session),
	  save_to_(std::move(save_to)),
	  given_histogram_(session.options().histogram),
	  play_(this)
{
	auto* panel = new wxPanel(this);
	auto* main = new wxBoxSizer(wxHORIZONTAL);
	auto* left = new wxBoxSizer(wxVERTICAL);
	// The window fits the screen (a 1280x720 laptop too): the image takes what
	// the controls' column leaves, and that column scrolls.
	const wxRect screen = wxDisplay(static_cast<unsigned>(std::max(0, wxDisplay::GetFromWindow(this)))).GetClientArea();
	const wxSize window(std::min(screen.width, 1600), std::min(screen.height, 1000));
	image_width_ = imageWidthFor(window);
	image_ = new wxGenericStaticBitmap(panel, wxID_ANY, wxBitmap(image_width_, image_width_ * 3 / 4));
	image_->SetToolTip("drag the centre, the base, max-range or horizon (R) circle, or the forward arrow; Shift+click "
					   "places the centre; the wheel zooms, a right-button drag pans");
	left->Add(image_, 0, wxALL, 4);
	auto* nav = new wxBoxSizer(wxHORIZONTAL);
	auto* prev = new wxButton(panel, wxID_ANY, "<", wxDefaultPosition, wxSize(36, -1));
	auto* next = new wxButton(panel, wxID_ANY, ">", wxDefaultPosition, wxSize(36, -1));
	auto* play = new wxButton(panel, wxID_ANY, "Play");
	slider_ = new wxSlider(panel, wxID_ANY, 0, 0, std::max(1, s_.frames() - 1));
	frame_label_ = new wxStaticText(panel, wxID_ANY, "frame 0 / 0");
	nav->Add(prev, 0, wxALL, 2);
	nav->Add(play, 0, wxALL, 2);
	nav->Add(next, 0, wxALL, 2);
	nav->Add(slider_, 1, wxALL | wxEXPAND, 2);
	nav->Add(frame_label_, 0, wxALL | wxALIGN_CENTER_VERTICAL, 4);
	left->Add(nav, 0, wxEXPAND);
	buildShowsAndActions(panel, left);  // under the image: always in view, however short the window
	main->Add(left, 0);

	// The middle column: the error plot, the scan from above, the bird's-eye view and the colours.
	auto* middle = new wxBoxSizer(wxVERTICAL);
	error_plot_ = new wxGenericStaticBitmap(panel, wxID_ANY, wxBitmap(kPlotSize, kErrorPlotHeight));
	error_plot_->SetToolTip("each frame's mean error over the whole log: laser cyan, truth white; its share of unsure "
							"rays as a pink bar; click to go to that frame");
	middle->Add(new wxStaticText(panel, wxID_ANY, "error per frame (click to go there)"), 0, wxALL, 2);
	middle->Add(error_plot_, 0, wxALL, 2);
	plot_ = new wxStaticBitmap(panel, wxID_ANY, wxBitmap(kPlotSize, kPlotSize));
	plot_->SetToolTip("the scan from above, forward up, 1 m circles, the max range grey: omnicam hit green, no hit "
					  "yellow, too close red, outlier magenta, unsure pink (at its confident extent); laser cyan; truth white");
	middle->Add(new wxStaticText(panel, wxID_ANY, "scan from above (laser cyan, truth white)"), 0, wxALL, 2);
	middle->Add(plot_, 0, wxALL, 2);
	auto* smalls = new wxBoxSizer(wxHORIZONTAL);
	birdseye_ = new wxStaticBitmap(panel, wxID_ANY, wxBitmap(kSmall, kSmall));
	colours_ = new wxStaticBitmap(panel, wxID_ANY, wxBitmap(kSmall, kSmall));
	birdseye_->SetToolTip("bird's-eye view of the floor (the paper's eqs. 1-3)");
	colours_->SetToolTip("the colours the classifier calls floor, most frequent first");
	smalls->Add(birdseye_, 0, wxALL, 2);
	smalls->Add(colours_, 0, wxALL, 2);
	middle->Add(new wxStaticText(panel, wxID_ANY, "bird's-eye view | colours called floor"), 0, wxALL, 2);
	middle->Add(smalls, 0);
	main->Add(middle, 0);

	// The right column: the frame's figures and a control per key, scrolled if the window is short.
	auto* column = new wxScrolledWindow(panel, wxID_ANY, wxDefaultPosition, wxSize(kControlsWidth, -1), wxVSCROLL);
	column->SetScrollRate(0, 12);
	auto* right = new wxBoxSizer(wxVERTICAL);
	frame_score_ = new wxStaticText(column, wxID_ANY, "");
	right->Add(frame_score_, 0, wxALL, 4);
	buildControls(column, right);
	column->SetSizer(right);
	column->FitInside();
	main->Add(column, 1, wxEXPAND);
	panel->SetSizer(main);
	auto* frame_sizer = new wxBoxSizer(wxVERTICAL);
	frame_sizer->Add(panel, 1, wxEXPAND);
	SetSizer(frame_sizer);
	CreateStatusBar(2);
	const int widths[] = {-1, -3};
	GetStatusBar()->SetStatusWidths(2, widths);
	SetSize(window);
	SetMinSize(wxSize(std::min(window.GetWidth(), 900), std::min(window.GetHeight(), 560)));
	Bind(wxEVT_SIZE, [this](wxSizeEvent& e) {
		e.Skip();
		const int width = imageWidthFor(GetClientSize());
		if (width != image_width_) image_width_ = width, refresh();
	});

	bindGuarded(prev, wxEVT_BUTTON, [this](wxCommandEvent&) { setFrame(frame_ - 1); });
	bindGuarded(next, wxEVT_BUTTON, [this](wxCommandEvent&) { setFrame(frame_ + 1); });
	bindGuarded(play, wxEVT_BUTTON, [this, play](wxCommandEvent&) {
		if (play_.IsRunning()) play_.Stop(), play->SetLabel("Play");
		else play_.Start(150), play->SetLabel("Stop");
	});
	bindGuarded(this, wxEVT_TIMER, [this](wxTimerEvent&) { setFrame(frame_ + 1 < s_.frames() ? frame_ + 1 : 0); });
	bindGuarded(slider_, wxEVT_SLIDER, [this](wxCommandEvent&) { setFrame(slider_->GetValue()); });
	bindGuarded(this, wxEVT_CHAR_HOOK, [this](wxKeyEvent& e) { onKey(e); });
	for (const auto type : {wxEVT_LEFT_DOWN, wxEVT_MOTION, wxEVT_LEFT_UP})
		bindGuarded(image_, type, [this](wxMouseEvent& e) { onImageMouse(e), e.Skip(); });
	for (const auto type : {wxEVT_MOUSEWHEEL, wxEVT_RIGHT_DOWN, wxEVT_MOTION})
		bindGuarded(image_, type, [this](wxMouseEvent& e) { onZoomOrPan(e), e.Skip(); });
	bindGuarded(error_plot_, wxEVT_LEFT_DOWN, [this](wxMouseEvent& e) {
		if (score_) setFrame(tuner::frameAtColumn(e.GetX(), error_plot_->GetSize().GetWidth(), s_.frames()));
	});
	Bind(wxEVT_CLOSE_WINDOW, &TunerFrame::onClose, this);

	controlsFromParams();
	setFrame(std::clamp(first_frame, 0, s_.frames() - 1));
	slider_->SetFocus();  // not a number field: the arrow keys step frames from the start
}

void TunerFrame::buildControls(wxWindow* p, wxSizer* sizer)
{
	auto* grid = new wxFlexGridSizer(2, 4, 8);  // label, control: narrow enough for the column
	const auto& table = RangefinderParams::table();
	const auto add = [&](const std::string& key, wxWindow* control, KeyControl c) {
		const FieldInfo& f = table.field(key).info;
		auto* label = new wxStaticText(p, wxID_ANY, wxString::FromUTF8(labelOf(f)));
		label->SetToolTip(tooltipOf(f)), control->SetToolTip(tooltipOf(f));
		grid->Add(label, 0, wxALIGN_CENTER_VERTICAL), grid->Add(control);
		c.key = key;
		controls_.push_back(c);
	};
	// A number's arrows step within its range; `shown` bounds those a range leaves open.
	const auto number = [&](const std::string& key, double inc, int digits, Range shown = Range::finite()) {
		const Range r = table.field(key).info.range.value_or(shown);
		const double lo = std::isfinite(r.lo) ? r.lo : shown.lo, hi = std::isfinite(r.hi) ? r.hi : shown.hi;
		auto* c = new wxSpinCtrlDouble(p, wxID_ANY, "", wxDefaultPosition, wxDefaultSize, wxSP_ARROW_KEYS, lo, hi,
									   lo, inc);
		c->SetDigits(digits);
		bindGuarded(c, wxEVT_SPINCTRLDOUBLE, [this](wxSpinDoubleEvent&) { onParamsChanged(); });
		add(key, c, {"", c, nullptr, nullptr});
		return c;
	};
	const auto choice = [&](const std::string& key) {
		auto* c = new wxChoice(p, wxID_ANY);
		for (const auto& name : table.field(key).info.choices) c->Append(wxString::FromUTF8(name));
		bindGuarded(c, wxEVT_CHOICE, [this](wxCommandEvent&) { onParamsChanged(); });
		add(key, c, {"", nullptr, c, nullptr});
	};
	const auto check = [&](const std::string& key) {
		auto* c = new wxCheckBox(p, wxID_ANY, "");
		bindGuarded(c, wxEVT_CHECKBOX, [this](wxCommandEvent&) { onParamsChanged(); });
		add(key, c, {"", nullptr, nullptr, c});
	};
	const Range pixels = Range::closed(0, kMaxImageSide);
	number("N", 1, 0), number("K", 1, 0);
	threshold_ = number("threshold", 0.0025, 4);
	number("step_threshold", 0.05, 2), choice("step_sign");
	choice("boundary_model"), choice("outlier_filter");
	number("cx", 0.5, 1, pixels), number("cy", 0.5, 1, pixels);
	number("R", 0.5, 1), number("forward_azimuth_deg", 1, 1, Range::closed(-360, 360));
	number("base_radius", 1, 1, pixels), number("min_range", 0.05, 2, Range::closed(0, 100));
	number("max_range", 0.1, 2, Range::closed(0, 100));
	check("mirrored"), check("wall_fit"), check("exposure_compensation");
	sizer->Add(grid, 0, wxALL, 4);
}

void TunerFrame::buildShowsAndActions(wxWindow* p, wxSizer* sizer)
{

	auto* shows = new wxWrapSizer(wxHORIZONTAL);
	const std::vector<std::pair<const char*, bool*>> boxes = {
		{"free", &overlay_.classification}, {"scanlines", &overlay_.scanlines}, {"rays", &overlay_.rays},
		{"K-rejected", &overlay_.candidates}, {"laser", &overlay_.laser},    {"truth", &overlay_.truth},
		{"set-up", &overlay_.camera},         {"legend", &overlay_.legend}};
	for (const auto& [name, flag] : boxes)
	{
		auto* box = new wxCheckBox(p, wxID_ANY, name);
		box->SetValue(*flag);
		bindGuarded(box, wxEVT_CHECKBOX, [this, flag = flag, box](wxCommandEvent&) {
			*flag = box->GetValue();
			refresh();
		});
		shows->Add(box, 0, wxALL, 2);
	}
	sizer->Add(shows, 0, wxALL, 2);

	auto* actions = new wxWrapSizer(wxHORIZONTAL);
	auto* score = new wxButton(p, wxID_ANY, "Score all frames");
	auto* train = new wxButton(p, wxID_ANY, "Train histogram here (Ctrl+H)");
	auto* save = new wxButton(p, wxID_ANY, "Save ini (Ctrl+S)");
	auto* undo = new wxButton(p, wxID_ANY, "Undo (Ctrl+Z)");
	auto* reset = new wxButton(p, wxID_ANY, "Reset to loaded");
	bindGuarded(undo, wxEVT_BUTTON, [this](wxCommandEvent&) {
		if (!s_.undo()) return status("nothing to undo");
		controlsFromParams(), rangefinder_changed_ = true, updateTitle(), refresh();
	});
	bindGuarded(reset, wxEVT_BUTTON, [this](wxCommandEvent&) { s_.resetToLoaded(), controlsFromParams(),
																rangefinder_changed_ = true, updateTitle(), refresh(); });
	bindGuarded(score, wxEVT_BUTTON, [this](wxCommandEvent&) { scoreAll(); });
	bindGuarded(train, wxEVT_BUTTON, [this](wxCommandEvent&) { this->train(); });
	bindGuarded(save, wxEVT_BUTTON, [this](wxCommandEvent&) { this->save(); });
	for (auto* b : {score, train, save, undo, reset}) actions->Add(b, 0, wxALL, 2);
	sizer->Add(actions, 0, wxALL, 2);
	auto* keys = new wxStaticText(p, wxID_ANY,
								  "keys: Page Up/Down frame (Left/Right too outside a number field), Home/End "
								  "first/last, [ and ] halve/double the threshold, Ctrl+T type the threshold, Ctrl+S "
								  "save, Ctrl+W close");
	keys->Wrap(std::max(kMinImageWidth, image_width_ - 10));
	sizer->Add(keys, 0, wxALL, 4);
}

void TunerFrame::controlsFromParams()
{
	updating_ = true;
	const RangefinderParams& p = s_.params();
	for (const auto& c : controls_)
	{
		const std::string value = RangefinderParams::table().field(c.key).print(p);
		if (c.number) c.number->SetValue(parseDouble(value));
		if (c.choice) c.choice->SetStringSelection(wxString::FromUTF8(value));
		if (c.check) c.check->SetValue(value == "true");
	}
	updating_ = false;
}

bool TunerFrame::applyControls()
{
	RangefinderParams p = s_.params();
	try
	{
		// Each key parsed and range-checked as an ini's value is, then validated as a whole.
		for (const auto& c : controls_)
		{
			const auto& field = RangefinderParams::table().field(c.key);
			const std::string text = shownText(c);
			try
			{
				field.set(p, text);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::invalid_argument(c.key + " '" + text + "': " + e.what());
			}
		}
		s_.changeParams(p);
	}
	catch (const std::exception& e)
	{
		controlsFromParams();  // back to the values in force, visibly
		status(wxString::FromUTF8(std::string("refused: ") + omnirange::app::errorText(e) + "; the values in force are shown again"),
			   Say::Error);
		return false;
	}
	controlsFromParams();  // the committed text, as the controls format it
	rangefinder_changed_ = true;
	updateTitle();
	return true;
}

void TunerFrame::onParamsChanged()
{
	if (!updating_ && applyControls()) refresh();
}

void TunerFrame::setFrame(int k)
{
	frame_ = std::clamp(k, 0, s_.frames() - 1);
	slider_->SetValue(frame_);
	frame_label_->SetLabel(wxString::Format("frame %d / %d", frame_, s_.frames() - 1));
	updateTitle();
	refresh();
}

void TunerFrame::updateTitle()
{
	// A leading '*' marks values not saved yet, as editors do.
	SetTitle(wxString::Format("%somnirange-tuner: frame %d / %d of %s", s_.unsaved() ? "*" : "", frame_,
							  s_.frames() - 1, s_.options().rawlog));
}

void TunerFrame::showUnreadable(const std::string& why)
{
	const RangefinderParams& p = s_.params();
	const cv::Size size(p.camera.image_width, p.camera.image_height);
	image_->SetBitmap(toBitmap(tuner::drawPlaceholder(size, "frame " + std::to_string(frame_) + ": " + why), image_width_));
	plot_->SetBitmap(toBitmap(tuner::drawPlaceholder({kPlotSize, kPlotSize}, "no scan"), kPlotSize));
	birdseye_->SetBitmap(toBitmap(tuner::drawPlaceholder({kSmall, kSmall}, ""), kSmall));
	frame_score_->SetLabel("frame " + std::to_string(frame_) + " cannot be shown");
	status(wxString::FromUTF8("frame " + std::to_string(frame_) + ": " + why), Say::Error);
}

void TunerFrame::refresh()
{
	const auto t0 = std::chrono::steady_clock::now();
	tuner::FrameScan scan;
	try
	{
		if (!s_.hasColours())
		{
			image_->SetBitmap(toBitmap(inView(s_.image(frame_)), image_width_));
			return status("no histogram: train one on this rawlog (Ctrl+H) or start with -H FILE", Say::Routine);
		}
		scan = s_.scan(frame_);
	}
	catch (const std::exception& e)
	{
		return showUnreadable(omnirange::app::errorText(e));
	}
	const Rangefinder& rf = s_.rangefinder();
	image_->SetBitmap(toBitmap(inView(tuner::drawOmniOverlay(scan, rf, overlay_)), image_width_));
	plot_->SetBitmap(toBitmap(tuner::drawScanPlot(scan, s_.params(), kPlotSize), kPlotSize));
	if (rangefinder_changed_)
	{
		view_ = std::make_unique<BirdsEyeView>(rf.camera(), kSmall, 2 * s_.params().scanner.max_range / kSmall);
		colours_->SetBitmap(toBitmap(tuner::drawFloorColours(s_.colours(), rf.classifier(), cv::Size(kSmall, kSmall)), kSmall));
		rangefinder_changed_ = false;
	}
	birdseye_->SetBitmap(toBitmap(view_->render(scan.bgr), kSmall));
	drawErrorPlot();
	const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	const int hits = scan.scan.count(RayStatus::Hit), rays = static_cast<int>(scan.scan.rays.size());
	wxString score = wxString::Format("hits %d, unsure %d of %d rays", hits, scan.scan.count(RayStatus::Unsure), rays);
	if (!scan.laser_pairs.empty())
	{
		const auto a = tuner::agreementOf(scan.laser_pairs);
		score += wxString::Format("; against the laser: mean abs %.3f m over %zu rays", a.mean_abs, a.compared);
	}
	frame_score_->SetLabel(score);
	status(wxString::Format("frame %d: scan %.1f ms, update %.1f ms", frame_, scan.scan_ms, ms), Say::Routine);
	Layout();
}

void TunerFrame::onKey(wxKeyEvent& e)
{
	const wxWindow* focus = wxWindow::FindFocus();
	const bool typing = dynamic_cast<const wxSpinCtrl*>(focus) || dynamic_cast<const wxSpinCtrlDouble*>(focus) ||
						(focus && focus->GetParent() && dynamic_cast<const wxSpinCtrlDouble*>(focus->GetParent()));
	const int code = e.GetKeyCode();
	const int key = code < 128 ? std::toupper(code) : code;
	if (e.ControlDown())
	{
		if (key == 'S') return static_cast<void>(save());
		if (key == 'H') return train();
		if (key == 'W' || key == 'Q') return static_cast<void>(Close());
		if (key == 'T') return threshold_->SetFocus(), threshold_->SetSelection(-1, -1);
		if (key == 'Z')
		{
			if (!s_.undo()) return status("nothing to undo");
			return controlsFromParams(), rangefinder_changed_ = true, updateTitle(), refresh();
		}
	}
	// Enter or Tab in a number field: take the text as typed, before GTK clamps it into the
	// field's range ("2" for a threshold would become 1 without a word); a refused one is said.
	if (typing && (key == WXK_RETURN || key == WXK_NUMPAD_ENTER || key == WXK_TAB))
	{
		if (applyControls()) refresh();
		if (key == WXK_TAB) e.Skip();
		return;
	}
	// Page Up/Down step frames whatever has the focus; a number field keeps its arrows and Home/End.
	if (key == WXK_PAGEDOWN) return setFrame(frame_ + 1);
	if (key == WXK_PAGEUP) return setFrame(frame_ - 1);
	if (!typing)
	{
		if (key == WXK_RIGHT) return setFrame(frame_ + 1);
		if (key == WXK_LEFT) return setFrame(frame_ - 1);
		if (key == WXK_HOME) return setFrame(0);
		if (key == WXK_END) return setFrame(s_.frames() - 1);
	}
	if (key == ']' || key == '[')  // a number field takes no brackets: these work wherever the focus is
	{
		threshold_->SetValue(std::clamp(threshold_->GetValue() * (key == ']' ? 2.0 : 0.5), 0.0, 1.0));
		return onParamsChanged();
	}
	e.Skip();
}

void TunerFrame::drawErrorPlot()
{
	const wxSize size = error_plot_->GetSize();
	error_plot_->SetBitmap(toBitmap(
		tuner::drawErrorPlot(score_.value_or(tuner::LogScore{}), frame_, {size.GetWidth(), size.GetHeight()}),
		size.GetWidth()));
}

void TunerFrame::change(const RangefinderParams& p)
{
	try
	{
		s_.changeParams(p);
	}
	catch (const std::exception& e)
	{
		return status(wxString::FromUTF8(std::string("refused: ") + omnirange::app::errorText(e)), Say::Error);
	}
	controlsFromParams(), rangefinder_changed_ = true, updateTitle(), refresh();
}

double TunerFrame::imageScale() const
{
	return static_cast<double>(s_.params().camera.image_width) / image_width_ / zoom_;
}

cv::Point2d TunerFrame::imagePixel(const wxPoint& at) const
{
	return view_origin_ + cv::Point2d(at.x, at.y) * imageScale();
}

cv::Mat TunerFrame::inView(const cv::Mat& image) const
{
	if (zoom_ <= 1) return image;
	const cv::Rect view(static_cast<int>(std::lround(view_origin_.x)), static_cast<int>(std::lround(view_origin_.y)),
						static_cast<int>(std::lround(image.cols / zoom_)), static_cast<int>(std::lround(image.rows / zoom_)));
	cv::Mat out;
	cv::resize(image(view & cv::Rect(0, 0, image.cols, image.rows)), out, image.size(), 0, 0, cv::INTER_NEAREST);
	return out;
}

void TunerFrame::onZoomOrPan(wxMouseEvent& e)
{
	const cv::Size size(s_.params().camera.image_width, s_.params().camera.image_height);
	const auto keepInside = [&] {
		view_origin_.x = std::clamp(view_origin_.x, 0.0, size.width * (1 - 1 / zoom_));
		view_origin_.y = std::clamp(view_origin_.y, 0.0, size.height * (1 - 1 / zoom_));
	};
	if (e.GetEventType() == wxEVT_MOUSEWHEEL)
	{
		const cv::Point2d under = imagePixel(e.GetPosition());
		zoom_ = std::clamp(zoom_ * (e.GetWheelRotation() > 0 ? 1.25 : 0.8), 1.0, 8.0);
		view_origin_ = under - cv::Point2d(e.GetX(), e.GetY()) * imageScale();  // the same pixel stays under the mouse
		keepInside();
		return refresh();
	}
	if (e.RightDown()) pan_from_ = e.GetPosition();
	if (e.Dragging() && e.RightIsDown())
	{
		view_origin_ -= cv::Point2d(e.GetX() - pan_from_.x, e.GetY() - pan_from_.y) * imageScale();
		pan_from_ = e.GetPosition();
		keepInside();
		refresh();
	}
}

TunerFrame::Handle TunerFrame::handleAt(const cv::Point2d& px) const
{
	if (!s_.hasColours()) return Handle::None;
	const Rangefinder& rf = s_.rangefinder();
	const CameraParams& cam = s_.params().camera;
	const double grab = kGrab * imageScale();
	const Pixel tip = rf.camera().pixelFromPolar(0.0, rf.scanner().maxRangeRho());
	if (std::hypot(px.x - tip.u, px.y - tip.v) <= 2 * grab) return Handle::Forward;
	const double d = std::hypot(px.x - cam.cx, px.y - cam.cy);
	if (d <= grab) return Handle::Centre;
	const std::pair<Handle, double> circles[] = {{Handle::Base, s_.params().scanner.base_radius},
												 {Handle::MaxRange, rf.scanner().maxRangeRho()},
												 {Handle::Horizon, rf.camera().horizonRho()}};
	Handle nearest = Handle::None;
	double best = grab;
	for (const auto& [h, rho] : circles)
		if (std::abs(d - rho) <= best) best = std::abs(d - rho), nearest = h;
	return nearest;
}

RangefinderParams TunerFrame::movedTo(Handle h, const cv::Point2d& px) const
{
	RangefinderParams p = s_.params();
	const double du = px.x - p.camera.cx, dv = px.y - p.camera.cy, rho = std::hypot(du, dv);
	switch (h)
	{
		case Handle::Centre: p.camera.cx = std::round(px.x * 2) / 2, p.camera.cy = std::round(px.y * 2) / 2; break;
		case Handle::Base: p.scanner.base_radius = std::round(rho); break;
		case Handle::MaxRange:
			p.scanner.max_range = std::round(s_.rangefinder().camera().distanceFromRho(rho) * 100) / 100;
			break;
		case Handle::Horizon:  // the horizon circle's radius is R for the paraboloid only
			if (p.camera.mirror_model != MirrorModel::Paraboloid)
				throw std::invalid_argument("the horizon circle is R's for the paraboloid only; set this mirror's model by its keys");
			p.camera.R = std::round(rho * 2) / 2;
			break;
		case Handle::Forward:  // counter-clockwise from +u as the picture is viewed
			p.camera.forward_azimuth = std::round(std::atan2(-dv, du) * 180 / M_PI) * M_PI / 180;
			break;
		case Handle::None: break;
	}
	return p;
}

void TunerFrame::onImageMouse(wxMouseEvent& e)
{
	const cv::Point2d px = imagePixel(e.GetPosition());
	if (e.LeftDown())
	{
		if (e.ShiftDown()) return change(movedTo(Handle::Centre, px));
		dragged_ = handleAt(px), drag_start_ = s_.params();
		if (dragged_ != Handle::None) image_->CaptureMouse();
		return;
	}
	if (dragged_ == Handle::None) return;
	if (e.Dragging() || e.LeftUp())
	{
		try
		{
			s_.setParams(movedTo(dragged_, px));  // live, while the button is down
		}
		catch (const std::exception& ex)
		{
			status(wxString::FromUTF8(std::string("refused: ") + omnirange::app::errorText(ex)), Say::Error);
		}
		controlsFromParams(), rangefinder_changed_ = true, refresh();
	}
	if (e.LeftUp())
	{
		if (image_->HasCapture()) image_->ReleaseMouse();
		dragged_ = Handle::None;
		const RangefinderParams end = s_.params();
		s_.setParams(drag_start_);
		change(end);  // one undo step for the whole drag
	}
}

bool TunerFrame::save()
{
	if (!applyControls()) return false;
	try
	{
		s_.saveIni(save_to_);
	}
	catch (const std::exception& e)
	{
		status(wxString::FromUTF8(omnirange::app::errorText(e)), Say::Error);
		return false;
	}
	status("saved [" + s_.options().section + "] to " + save_to_);
	updateTitle();
	refresh();
	return true;
}

void TunerFrame::onClose(wxCloseEvent& e)
{
	if (e.CanVeto() && (!applyControls() || s_.unsaved()))
	{
		wxMessageDialog ask(this, "Save the changed values into " + save_to_ + " before closing?",
							"omnirange-tuner: unsaved changes", wxYES_NO | wxCANCEL | wxYES_DEFAULT | wxICON_QUESTION);
		ask.SetYesNoCancelLabels("Save", "Discard", "Cancel");
		const int answer = ask.ShowModal();
		if (answer == wxID_CANCEL || (answer == wxID_YES && !save())) return e.Veto();
	}
	play_.Stop();
	Destroy();
}

void TunerFrame::scoreAll()
{
	if (!s_.hasColours()) return status("no histogram yet: train one first", Say::Error);
	wxProgressDialog progress("omnirange-tuner", "scanning every frame", s_.frames(), this, wxPD_APP_MODAL | wxPD_AUTO_HIDE);
	const auto a = s_.scoreAll([&](int done, int) { progress.Update(done); });
	score_ = a;
	if (a.compared == 0)  // a mean over nothing would read as a perfect score
		return status("whole rawlog: nothing to score against: no laser scan pairs with an image, or none with a hit",
					  Say::Error);
	wxString text = wxString::Format("whole rawlog: mean abs %.4f m over %zu rays of %d frames with a laser",
									 a.mean_abs, a.compared, a.frames);
	if (a.unreadable > 0) text += wxString::Format(" (%d frames could not be read and are left out)", a.unreadable);
	if (s_.params().asIni() != s_.loaded().asIni())  // A/B: the same log with the values the ini held
	{
		const auto b = s_.scoreWith(s_.loaded(), [&](int done, int) { progress.Update(done); });
		text += wxString::Format("; with the values loaded: %.4f m over %zu rays", b.mean_abs, b.compared);
	}
	status(text);
	refresh();
}

void TunerFrame::train()
{
	const std::string out = std::filesystem::path(save_to_).replace_extension(".hist").string();
	const bool exists = std::filesystem::exists(out);
	try  // only a colour model is replaced, never an input or another file: said before asking
	{
		requireOutputAllowed(out, OutputKind::Histogram, "omnirange-tuner",
							 {s_.options().rawlog, s_.options().ini}, false);
	}
	catch (const std::exception& e)
	{
		return status(wxString::FromUTF8(omnirange::app::errorText(e)), Say::Error);
	}
	// Through a link it may be the histogram the window was opened with: say so in the question.
	std::error_code ec;
	const bool in_use = exists && !given_histogram_.empty() &&
						std::filesystem::equivalent(out, given_histogram_, ec);
	const std::string what = in_use && std::filesystem::is_symlink(out, ec)
								 ? out + " (a link to " + given_histogram_ + ", the histogram in use)"
								 : in_use ? out + ", the histogram in use," : out;
	if (exists && wxMessageDialog(this, what + " is a colour model already. Train a new one and replace it?",
								  "omnirange-tuner: replace the histogram?", wxYES_NO | wxNO_DEFAULT | wxICON_WARNING)
						  .ShowModal() != wxID_YES)
		return status("not trained: " + out + " kept");
	try
	{
		// Checked again: the file may have changed while the question was open.
		requireOutputAllowed(out, OutputKind::Histogram, "omnirange-tuner",
							 {s_.options().rawlog, s_.options().ini}, false);
		wxProgressDialog dialog("omnirange-tuner", "training the floor's colours on this rawlog", 100, this,
								wxPD_APP_MODAL | wxPD_AUTO_HIDE);
		const auto r = s_.train(out, {}, [&](std::size_t objects) {
			dialog.Pulse(wxString::Format("training the floor's colours: %zu objects read", objects));
		});
		status(wxString::Format("trained on %d pairs, %zu floor pixels -> %s", r.used, r.pixels, out));
	}
	catch (const std::exception& e)
	{
		return status(wxString::FromUTF8(omnirange::app::errorText(e)), Say::Error);
	}
	rangefinder_changed_ = true;
	refresh();
}

void TunerFrame::status(const wxString& text, Say how)
{
	const wxString line = how == Say::Error ? "error: " + text : text;
	// Two fields: the frame's timings, and the last result or error, which stays until the next one.
	GetStatusBar()->SetStatusText(line, how == Say::Routine ? 0 : 1);
	if (how != Say::Routine) std::cout << "omnirange-tuner: " << line.ToStdString() << std::endl;
}
