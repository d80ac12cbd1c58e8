#pragma once
// The Variants menu (KHR_materials_variants): "Default materials" and one entry per
// variant of the open file, disabled when it has none. Choosing one switches the
// materials on the render thread without reloading the file
// (render::set_material_variant: only the primitives' material indices change) and says
// what changed, GPU bytes included, through switched(). Self-contained: the window
// adds it to the menu bar and gives it a way to post render-thread tasks.
#include <QMenu>
#include <QString>

#include <functional>

namespace sherpa::render {
struct VariantSwitch;
} // namespace sherpa::render

class QActionGroup;
class QEvent;

namespace sherpa::editor {

class EditorContext;
class GpuViewport;

class VariantMenu : public QMenu {
    Q_OBJECT
public:
    using Task = std::function<void(GpuViewport&)>;
    using Poster = std::function<void(Task)>; // runs a task on the render thread
    VariantMenu(EditorContext& context, Poster post, QWidget* parent);

    int variant() const { return variant_; } // -1: the default materials
    // Shows `variant` (-1: the defaults); a variant the scene lacks is ignored.
    void choose(int variant);
    // The log line for a switch: variant name, primitives, instances, GPU bytes.
    static QString describe(const render::VariantSwitch& s, const QString& name);

Q_SIGNALS:
    void switched(const QString& message); // after the render thread switched

protected:
    void changeEvent(QEvent* event) override;

private:
    void rebuild(); // from the context's scene (a new scene shows its defaults)
    void retranslate();

    EditorContext& context_;
    Poster post_;
    QActionGroup* group_;
    int variant_ = -1;
};

} // namespace sherpa::editor
