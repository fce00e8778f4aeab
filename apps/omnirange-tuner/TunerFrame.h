#pragma once
// omnirange-tuner's window: a thin view over tuner::TunerSession. Every
// control change re-scans the frame and redraws (tuner/Overlays.h draws).
// No handler lets an exception out: what fails is said in the status bar
// (and on stdout), and the user's unsaved values stay.

#include <omnirange_tuner/Overlays.h>
#include <omnirange_tuner/TunerSession.h>

#include <omnirange/train/BirdsEyeView.h>

#include <wx/checkbox.h>
#include <wx/choice.h>
#include <wx/frame.h>
#include <wx/generic/statbmpg.h>
#include <wx/slider.h>
#include <wx/spinctrl.h>
#include <wx/statbmp.h>
#include <wx/stattext.h>
#include <wx/timer.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class TunerFrame : public wxFrame
{
   public:
	/** `save_to`: the ini that Save (Ctrl+S) writes the [section] keys into. */
	TunerFrame(omnirange::tuner::TunerSession& session, std::string save_to, int first_frame);

   private:
	/** Binds `handler` to `type` on `source` so that what it throws is shown, not fatal. */
	template <class Event, class Handler>
	void bindGuarded(wxEvtHandler* source, const wxEventTypeTag<Event>& type, Handler handler);
	/** A control per tunable key. */
	void buildControls(wxWindow* parent, wxSizer* sizer);
	/** The overlays' switches, the buttons and the keys' legend. */
	void buildShowsAndActions(wxWindow* parent, wxSizer* sizer);
	void controlsFromParams();
	/** Takes the controls' values, typed text not yet committed included;
	 * a refused value puts every control back to the value in force. */
	bool applyControls();
	void onParamsChanged();
	void setFrame(int k);
	void refresh();
	void showUnreadable(const std::string& why);
	void updateTitle();
	void onKey(wxKeyEvent& e);
	void onClose(wxCloseEvent& e);
	bool save();
	void scoreAll();
	void train();
	enum class Say { Routine, Note, Error };  // Note and Error are also printed on stdout
	void status(const wxString& text, Say how = Say::Note);

	/** The omnicam image's shown width for a client area of `client`. */
	static int imageWidthFor(const wxSize& client);

	omnirange::tuner::TunerSession& s_;
	int image_width_{768};
	std::string save_to_;
	std::string given_histogram_;  // -H: an input, whatever Train makes later
	omnirange::tuner::OverlayOptions overlay_;
	int frame_{0};
	bool updating_{false};  // controls being set from the parameters

	wxStaticBitmap *plot_{}, *birdseye_{}, *colours_{};
	// Windows of their own (a native static bitmap gets no mouse): the image
	// takes drags and clicks, the error plot clicks.
	wxGenericStaticBitmap *image_{}, *error_plot_{};
	std::optional<omnirange::tuner::LogScore> score_;  ///< the last "Score all frames", for the error plot

	/** What a drag on the image moves: the centre, the set-up's circles, the forward arrow. */
	enum class Handle { None, Centre, Base, MaxRange, Horizon, Forward };
	Handle dragged_{Handle::None};
	omnirange::RangefinderParams drag_start_;
	/** Zoom (1: the whole image) and the image pixel at the view's top left. */
	double zoom_{1};
	cv::Point2d view_origin_{0, 0};
	wxPoint pan_from_;  ///< where a right-button drag that pans started
	/** The part of the image in view, scaled to the shown width. */
	cv::Mat inView(const cv::Mat& image) const;
	/** [image px per display px] at the current zoom. */
	double imageScale() const;
	/** The image pixel under the mouse at display position `at`. */
	cv::Point2d imagePixel(const wxPoint& at) const;
	/** The wheel zooms about the pixel under the mouse; a right-button drag pans. */
	void onZoomOrPan(wxMouseEvent& e);
	Handle handleAt(const cv::Point2d& px) const;
	void onImageMouse(wxMouseEvent& e);
	/** The parameters with the dragged handle (or, with Shift, the centre) at `px`. */
	omnirange::RangefinderParams movedTo(Handle h, const cv::Point2d& px) const;
	void drawErrorPlot();
	/** Takes `p` as a change that Ctrl+Z undoes; refused values are said. */
	void change(const omnirange::RangefinderParams& p);
	wxSlider* slider_{};
	wxStaticText *frame_label_{}, *frame_score_{};
	/** A control for one key of the rangefinder's options table, which gives
	 * its label, unit, tooltip, range and an enum's names. */
	struct KeyControl
	{
		std::string key;
		wxSpinCtrlDouble* number{};
		wxChoice* choice{};
		wxCheckBox* check{};
	};
	std::vector<KeyControl> controls_;
	wxSpinCtrlDouble* threshold_{};  // the keys [, ] and Ctrl+T act on it
	wxTimer play_;
	// What depends on the rangefinder only, not on the frame: rebuilt when it changes.
	std::unique_ptr<omnirange::BirdsEyeView> view_;
	bool rangefinder_changed_{true};
};
