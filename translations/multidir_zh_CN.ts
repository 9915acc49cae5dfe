<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>AddPlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="50"/>
        <source>Add plane %1</source>
        <translation>添加平面 %1</translation>
    </message>
</context>
<context>
    <name>DeletePlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="55"/>
        <source>Delete plane %1</source>
        <translation>删除平面 %1</translation>
    </message>
</context>
<context>
    <name>DeviceReading</name>
    <message>
        <location filename="../ui/device/device_reading.cpp" line="15"/>
        <source>unknown: not read yet</source>
        <translation>未知：尚未读取</translation>
    </message>
    <message>
        <location filename="../ui/device/device_reading.cpp" line="18"/>
        <source>unknown since %1 (last read: %2)</source>
        <translation>自 %1 起未知（上次读取：%2）</translation>
    </message>
</context>
<context>
    <name>GcodeExport</name>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="75"/>
        <source>Could not write %1: %2. Check that the folder can be written and the disk is not full.</source>
        <translation>无法写入 %1：%2。请检查文件夹是否可写入以及磁盘是否已满。</translation>
    </message>
    <message>
        <source>Could not replace %1: it is in use or read-only.</source>
        <translation type="vanished">无法替换 %1：该文件正在使用或为只读。</translation>
    </message>
    <message>
        <source>Could not move %1 into place.</source>
        <translation type="vanished">无法将 %1 移动到目标位置。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="35"/>
        <source>There is no sliced job to export: slice the plan first.</source>
        <translation>没有可导出的切片作业：请先对方案切片。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="40"/>
        <source>%1 is a file, not a folder: choose a folder for the G-code.</source>
        <translation>%1 是文件而不是文件夹：请为 G 代码选择一个文件夹。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="45"/>
        <source>Could not create the folder %1: check that its parent exists and can be written.</source>
        <translation>无法创建文件夹 %1：请检查其上级文件夹是否存在且可写入。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="51"/>
        <location filename="../ui/slicing/gcode_export.cpp" line="66"/>
        <location filename="../ui/slicing/gcode_export.cpp" line="83"/>
        <source>Could not export the G-code: %1</source>
        <translation>无法导出 G 代码：%1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="57"/>
        <source>%1 holds files that are not a MultiDir job (%2 is one), so nothing was exported: choose an empty folder or one holding an earlier job.</source>
        <translation>%1 中有不属于 MultiDir 作业的文件（例如 %2），因此未导出任何内容：请选择空文件夹或存有先前作业的文件夹。</translation>
    </message>
</context>
<context>
    <name>MovePlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="39"/>
        <source>Move plane %1</source>
        <translation>移动平面 %1</translation>
    </message>
</context>
<context>
    <name>PlanEditRefusal</name>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="38"/>
        <source>The edit was not applied: %1 (%2)</source>
        <translation>编辑未被应用：%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="43"/>
        <source>Plane %1 would cut the platform region: move it up or tilt it less.</source>
        <translation>平面 %1 会切入平台区域：请将其上移或减小倾斜。</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="45"/>
        <source>Plane %1 would leave a piece below it that no longer stands on the platform: move or tilt it so that the part below stays in one piece on the platform.</source>
        <translation>平面 %1 会在其下方留下一块不再立于平台上的部分：请移动或倾斜该平面，使其下方部分作为一个整体留在平台上。</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="50"/>
        <source>The machine cannot print along the normal of plane %1: tilt it back within the machine&apos;s limits.</source>
        <translation>机器无法沿平面 %1 的法向打印：请将其倾斜回机器的限制范围内。</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="54"/>
        <source>Plane %1 would cut nothing off: move it into the part it cuts.</source>
        <translation>平面 %1 不会切下任何部分：请将其移入它所切割的部分。</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="56"/>
        <source>Plane %1 would leave nothing below it on the platform: move it up.</source>
        <translation>平面 %1 下方不会在平台上留下任何部分：请将其上移。</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="57"/>
        <source>Plane %1 was refused: %2</source>
        <translation>平面 %1 被拒绝：%2</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="66"/>
        <source>Plane %1 was not changed: with it there, plane %2 is refused. %3</source>
        <translation>平面 %1 未更改：它在该位置时，平面 %2 被拒绝。%3</translation>
    </message>
</context>
<context>
    <name>ReplacePlanCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="59"/>
        <source>New search</source>
        <translation>新搜索</translation>
    </message>
</context>
<context>
    <name>TiltPlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="45"/>
        <source>Tilt plane %1</source>
        <translation>倾斜平面 %1</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ApartJobRunner</name>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="16"/>
        <source>Slicing plate %1 of %2</source>
        <translation>正在切片打印板 %1（共 %2 个）</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="19"/>
        <source>Slicing the model in one piece with supports, for comparison</source>
        <translation>正在将模型作为整体连同支撑切片（用于比较）</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="20"/>
        <source>Cutting the parts to fit the printer</source>
        <translation>正在切割零件以适合打印机</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="21"/>
        <source>Placing the dowels</source>
        <translation>正在放置定位销</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="22"/>
        <source>Drilling the dowel holes</source>
        <translation>正在钻定位销孔</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="23"/>
        <source>Sinking the part numbers</source>
        <translation>正在刻入零件编号</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="24"/>
        <source>Laying the parts on plates</source>
        <translation>正在将零件排布到打印板上</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="25"/>
        <source>Writing the parts and the 3MF</source>
        <translation>正在写入零件和 3MF</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="26"/>
        <source>Drawing the assembly sheet</source>
        <translation>正在绘制装配图</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="33"/>
        <source>A part does not fit this printer even cut further: choose a printer with a larger bed, or scale the model down and search again.</source>
        <translation>即使进一步切割，仍有零件无法放入此打印机：请选择打印床更大的打印机，或缩小模型后重新搜索。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="37"/>
        <source>The slicer &apos;prusa-slicer&apos; was not found: install PrusaSlicer (scripts/install-deps.sh), or untick &quot;Slice the plates&quot;.</source>
        <translation>未找到切片软件 &apos;prusa-slicer&apos;：请安装 PrusaSlicer（scripts/install-deps.sh），或取消勾选“对打印板切片”。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="41"/>
        <source>The slicer failed on a plate: its command and last output lines are below. Try another printer, or untick &quot;Slice the plates&quot; to get the parts without G-code.</source>
        <translation>切片软件在某个打印板上失败：其命令和最后几行输出见下方。请尝试其他打印机，或取消勾选“对打印板切片”以获取不含 G 代码的零件。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="45"/>
        <source>The parts could not be laid out or the dowels not placed: the reason is below. Choose a printer with a larger bed or other dowel options.</source>
        <translation>无法排布零件或放置定位销：原因见下方。请选择打印床更大的打印机或其他定位销选项。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="49"/>
        <source>Drilling the dowel holes or sinking the numbers failed on a part (named below): try a smaller dowel diameter or another plan.</source>
        <translation>在某个零件（见下方名称）上钻定位销孔或刻入编号失败：请尝试更小的定位销直径或其他方案。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="75"/>
        <source>The plan is being printed apart already.</source>
        <translation>该方案已在分开打印中。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="79"/>
        <source>There is no plan to print apart: search the model first.</source>
        <translation>没有可分开打印的方案：请先对模型进行搜索。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="101"/>
        <source>Could not create a temporary folder for the parts: %1</source>
        <translation>无法为零件创建临时文件夹：%1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="97"/>
        <source>Not enough memory to print this plan apart.</source>
        <translation>内存不足，无法分开打印此方案。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="98"/>
        <source>Unexpected error while printing the plan apart.</source>
        <translation>分开打印方案时发生意外错误。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ApartPanel</name>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="129"/>
        <source>The parts must fit this printer&apos;s bed and height; its settings slice the plates</source>
        <translation>零件必须适合此打印机的打印床和高度；使用其设置对打印板切片</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="130"/>
        <source>Printer</source>
        <translation>打印机</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="131"/>
        <source>Slice the plates (PrusaSlicer) for the estimates</source>
        <translation>对打印板切片（PrusaSlicer）以进行估算</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="143"/>
        <source>Dowel diameter from</source>
        <translation>定位销直径下限</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="144"/>
        <source>Dowel diameter up to</source>
        <translation>定位销直径上限</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="145"/>
        <source>Clearance in radius</source>
        <translation>半径间隙</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="146"/>
        <source>Clearance in depth</source>
        <translation>深度间隙</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="147"/>
        <source>Wall around holes</source>
        <translation>孔周壁厚</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="148"/>
        <source>Dowels per joint</source>
        <translation>每个接合处的定位销数</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="152"/>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="154"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="156"/>
        <source>Export...</source>
        <translation>导出...</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="158"/>
        <source>Write every part and dowel (STL), the 3MF, the G-code of every plate, the assembly sheet and apart.json to a folder</source>
        <translation>将每个零件和定位销（STL）、3MF、每个打印板的 G 代码、装配图和 apart.json 写入文件夹</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Print</source>
        <translation>打印</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Filament
(cm³)</source>
        <translation>耗材
(cm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Support
(cm³)</source>
        <translation>支撑
(cm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="217"/>
        <source>Cancelled: nothing was written.</source>
        <translation>已取消：未写入任何内容。</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="241"/>
        <source>Assembly of %1</source>
        <translation>%1 的装配</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="249"/>
        <source>There is no plan to print apart: search the model first.</source>
        <translation>没有可分开打印的方案：请先对模型进行搜索。</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="254"/>
        <source>The printer &apos;%1&apos; could not be read: choose another one.</source>
        <translation>无法读取打印机“%1”：请选择其他打印机。</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="258"/>
        <source>The dowel options do not fit together: %1</source>
        <translation>定位销选项相互矛盾：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="276"/>
        <source>Nothing to export: run Print apart first.</source>
        <translation>没有可导出的内容：请先运行“分开打印”。</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="280"/>
        <source>The files could not be written: %1</source>
        <translation>无法写入文件：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/apart_panel.cpp" line="283"/>
        <source>%n file(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 个文件写入 %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="288"/>
        <source>Export the parts to a folder</source>
        <translation>将零件导出到文件夹</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="311"/>
        <source>%1 parts, %2 joints, %3 dowels, %4 plates; J_G apart %5 mm² (the plan: %6 mm²)</source>
        <translation>%1 个零件，%2 个接合处，%3 个定位销，%4 个打印板；分开打印 J_G %5 mm²（方案：%6 mm²）</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="317"/>
        <source>Parts exploded</source>
        <translation>零件爆炸视图</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="318"/>
        <location filename="../ui/panels/apart_panel.cpp" line="351"/>
        <source>Plate %1</source>
        <translation>打印板 %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="352"/>
        <source>All plates</source>
        <translation>所有打印板</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="353"/>
        <source>One piece with supports</source>
        <translation>整体连同支撑</translation>
    </message>
</context>
<context>
    <name>multidir::ui::Autosave</name>
    <message>
        <location filename="../ui/project/autosave.cpp" line="83"/>
        <source>Cannot create the autosave folder %1.</source>
        <translation>无法创建自动保存文件夹 %1。</translation>
    </message>
    <message>
        <location filename="../ui/project/autosave.cpp" line="91"/>
        <source>Cannot lock a new autosave file in %1.</source>
        <translation>无法在 %1 中锁定新的自动保存文件。</translation>
    </message>
    <message>
        <location filename="../ui/project/autosave.cpp" line="95"/>
        <source>Autosave failed: %1 (%2)</source>
        <translation>自动保存失败：%1（%2）</translation>
    </message>
</context>
<context>
    <name>multidir::ui::AxisPicker</name>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="17"/>
        <source>Open a model first: the rotation axis is picked on the platform under it.</source>
        <translation>请先打开一个模型：旋转轴在模型下方的平台上选取。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="26"/>
        <source>Click the first point on the platform (Esc cancels).</source>
        <translation>请在平台上点击第一个点（按 Esc 取消）。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="35"/>
        <location filename="../ui/viewer/axis_picker.cpp" line="41"/>
        <source>Picking the rotation axis was cancelled.</source>
        <translation>已取消选取旋转轴。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="49"/>
        <source>Click the second point on the platform: the axis runs from the first point to it.</source>
        <translation>请在平台上点击第二个点：轴从第一个点指向该点。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="54"/>
        <source>The second point is less than %1 mm from the first: click farther away.</source>
        <translation>第二个点与第一个点相距不到 %1 mm：请在更远处点击。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="61"/>
        <source>Rotation axis picked: (%1, %2, %3).</source>
        <translation>已选取旋转轴：（%1, %2, %3）。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="71"/>
        <source>The view looks along the platform: turn the view and click again.</source>
        <translation>视线与平台平行：请转动视图后重新点击。</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="79"/>
        <source>That click missed the platform: click on the grey disc under the model.</source>
        <translation>该点击未落在平台上：请点击模型下方的灰色圆盘。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::CellPanel</name>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="54"/>
        <source>Robot cell: the arm carries the platform under a fixed extruder</source>
        <translation>机器人单元：机械臂在固定挤出机下方承载平台</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="58"/>
        <source> mm</source>
        <translation> 毫米</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="59"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="69"/>
        <source>The nozzle tip in the robot base frame (measure it with the TCP; docs/robot-cell.md)</source>
        <translation>喷嘴尖端在机器人基坐标系中的位置（用 TCP 测量；docs/robot-cell.md）</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="70"/>
        <source>Unit vector from the tip up into the extruder, robot base frame</source>
        <translation>从喷嘴尖端向上指入挤出机的单位向量，机器人基坐标系</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="71"/>
        <source>Flange to platform centre (the TCP): translation; the calibration</source>
        <translation>法兰到平台中心（TCP）：平移；即标定值</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="72"/>
        <source>Flange to platform centre: rotation vector (axis times angle), degrees</source>
        <translation>法兰到平台中心：旋转向量（轴乘以角度），单位为度</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="74"/>
        <source>Load cell...</source>
        <translation>加载单元...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="76"/>
        <source>Save cell...</source>
        <translation>保存单元...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="86"/>
        <source>Find extruder position</source>
        <translation>查找挤出机位置</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="88"/>
        <source>Scores nozzle positions over the arm&apos;s workspace by the share of the plan&apos;s platform poses reachable with margin (multidir cell reach)</source>
        <translation>按方案中可留有余量到达的平台姿态所占比例，对机械臂工作空间内的喷嘴位置评分（multidir cell reach）</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="90"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="100"/>
        <source>Use this position</source>
        <translation>使用此位置</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="106"/>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="107"/>
        <source>Nozzle tip:</source>
        <translation>喷嘴尖端：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="108"/>
        <source>Nozzle axis:</source>
        <translation>喷嘴轴线：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="109"/>
        <source>Flange to platform:</source>
        <translation>法兰到平台：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="110"/>
        <source>Platform rotation:</source>
        <translation>平台旋转：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="111"/>
        <source>Table height:</source>
        <translation>工作台高度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="137"/>
        <source>Load robot cell</source>
        <translation>加载机器人单元</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="137"/>
        <location filename="../ui/panels/cell_panel.cpp" line="141"/>
        <source>Robot cell (*.json)</source>
        <translation>机器人单元 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="141"/>
        <source>Save robot cell</source>
        <translation>保存机器人单元</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="155"/>
        <source>Finding the extruder position was cancelled.</source>
        <translation>已取消查找挤出机位置。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="189"/>
        <source>Could not load the cell file %1: %2</source>
        <translation>无法加载单元文件 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="195"/>
        <source>Cell loaded from %1.</source>
        <translation>已从 %1 加载单元。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="201"/>
        <source>There is no cell to save.</source>
        <translation>没有可保存的单元。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="206"/>
        <source>Could not save the cell: %1</source>
        <translation>无法保存单元：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="209"/>
        <source>Cell saved as %1.</source>
        <translation>单元已保存为 %1。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="223"/>
        <source>No cell.</source>
        <translation>无单元。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="241"/>
        <source>Cell check: sound (%1, nozzle tip at %2, %3, %4 mm).</source>
        <translation>单元检查：正常（%1，喷嘴尖端位于 %2, %3, %4 mm）。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/cell_panel.cpp" line="248"/>
        <source>Cell check: %n problem(s)</source>
        <translation>
            <numerusform>单元检查：%n 个问题</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="293"/>
        <source>There is no cell: choose the robot cell machine or load a cell file.</source>
        <translation>没有单元：请选择机器人单元机器，或加载单元文件。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="298"/>
        <source>There is no plan: the reach map scores the plan&apos;s platform poses. Run a search or open a plan.</source>
        <translation>没有方案：可达性图对方案的平台姿态评分。请运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="303"/>
        <source>The plan&apos;s poses cannot be found: %1</source>
        <translation>无法求得方案的姿态：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="328"/>
        <source>The reach map failed: %1</source>
        <translation>可达性图计算失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="346"/>
        <source>Best nozzle position: %1, %2, %3 mm, %4 % of the plan&apos;s poses reachable with margin (least reach margin %5 mm) over %6 positions.</source>
        <translation>最佳喷嘴位置：%1, %2, %3 mm，方案中 %4 % 的姿态可留有余量到达（最小可达余量 %5 mm），共评估 %6 个位置。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="364"/>
        <source>Finding the extruder position...</source>
        <translation>正在查找挤出机位置...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="387"/>
        <source>The nozzle tip is now at the reach map&apos;s best position; move the extruder there and measure it again.</source>
        <translation>喷嘴尖端现已设在可达性图的最佳位置；请将挤出机移到该处并重新测量。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="160"/>
        <source>The cell changed since the reach map was made (the map scores the arm, the nozzle axis, the platform, the table and the margins it had): find the extruder position again.</source>
        <translation>自可达性图生成以来，单元已更改（该图按当时的机械臂、喷嘴轴线、平台、工作台和余量评分）：请重新查找挤出机位置。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="165"/>
        <source>The plan changed since the reach map was made (the map scores the plan&apos;s poses): find the extruder position again.</source>
        <translation>自可达性图生成以来，方案已更改（该图按方案的姿态评分）：请重新查找挤出机位置。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="175"/>
        <source>Supports were grown for the plan since the reach map was made (the map scores their poses too): find the extruder position again.</source>
        <translation>自可达性图生成以来，已为方案生成支撑（该图也按支撑的姿态评分）：请重新查找挤出机位置。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="337"/>
        <source>The plan or the cell changed while the reach map was made: find the extruder position again.</source>
        <translation>生成可达性图期间方案或单元已更改：请重新查找挤出机位置。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::CellViewPanel</name>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="31"/>
        <source>Show on the cell</source>
        <translation>在单元上显示</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="33"/>
        <source>The sliced job on the robot cell: the arm, the platform and the part at the poses the robot programs command (multidir robot-program)</source>
        <translation>机器人单元上的切片作业：机械臂、平台和零件处于机器人程序所指令的姿态（multidir robot-program）</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="35"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="38"/>
        <source>Back to the plan</source>
        <translation>返回方案</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="47"/>
        <location filename="../ui/panels/cell_view_panel.cpp" line="96"/>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="96"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="114"/>
        <source>Cancelled.</source>
        <translation>已取消。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="123"/>
        <source>The cell changed: show the job on it again.</source>
        <translation>单元已更改：请重新在其上显示作业。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="134"/>
        <source>There is no robot cell: choose the machine &quot;robot arm under a fixed extruder&quot;.</source>
        <translation>没有机器人单元：请选择机器“固定挤出机下的机械臂”。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="138"/>
        <source>The plan is not sliced: slice it with the cell&apos;s profile (ur5-cell-0.8) first.</source>
        <translation>方案尚未切片：请先用单元的配置（ur5-cell-0.8）对其切片。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="162"/>
        <source>The job cannot be posed on the cell: %1</source>
        <translation>无法在单元上摆放作业：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="174"/>
        <source>Converting the job for the cell...</source>
        <translation>正在为单元转换作业...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/cell_view_panel.cpp" line="244"/>
        <source>%n step(s) on the %1, %2 moves.</source>
        <translation>
            <numerusform>%1 上的 %n 个步骤，%2 次移动。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="268"/>
        <source>Step %1 of %2: no move converted (the arm at home).</source>
        <translation>第 %1 步（共 %2 步）：未转换任何移动（机械臂处于原位）。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="272"/>
        <source>Step %1 of %2, move %3 of %4 (%5, line %6)</source>
        <translation>第 %1 步（共 %2 步），移动 %3/%4（%5，第 %6 行）</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="61"/>
        <source>Show the reach map</source>
        <translation>显示可达性图</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="63"/>
        <source>The nozzle positions &quot;Find extruder position&quot; scored (Machine tab), coloured from red (none of the plan&apos;s poses reachable with margin) to blue (all of them); the best one ringed in white</source>
        <translation>“查找挤出机位置”评分的喷嘴位置（机器选项卡），颜色从红色（方案的姿态均无法留有余量地到达）到蓝色（全部可达）；最佳位置以白圈标出</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="196"/>
        <source>Reach map: %1 nozzle positions every %2 mm; the best, ringed, at %3, %4, %5 mm with %6 % of the plan&apos;s poses reachable with margin.</source>
        <translation>可达性图：%1 个喷嘴位置，间距 %2 mm；最佳位置（圈出）位于 %3, %4, %5 mm，方案姿态中 %6 % 可留有余量地到达。</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="205"/>
        <source>Reach map not shown: %1</source>
        <translation>未显示可达性图：%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="229"/>
        <source>Plan&apos;s poses reachable with margin (%)</source>
        <translation>可留有余量到达的方案姿态 (%)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ConnectionForm</name>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="37"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>旋转平台（4 自由度）</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="38"/>
        <source>Robot arm (5-DOF)</source>
        <translation>机械臂（5 自由度）</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="40"/>
        <source>Robot cell (5-DOF, fixed extruder)</source>
        <translation>机器人单元（5 自由度，固定挤出头）</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="42"/>
        <source>Robot cell (5-DOF, Universal Robots: the arm carries the part under a fixed extruder)</source>
        <translation>机器人单元（5 自由度，Universal Robots：机械臂携带零件在固定挤出头下移动）</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="47"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="48"/>
        <source>Modbus RTU (serial)</source>
        <translation>Modbus RTU（串口）</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="57"/>
        <source>Host:</source>
        <translation>主机：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="58"/>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="59"/>
        <source>Unit id:</source>
        <translation>单元 ID：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="74"/>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="75"/>
        <source>Even</source>
        <translation>偶校验</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="76"/>
        <source>Odd</source>
        <translation>奇校验</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="80"/>
        <source>Serial port:</source>
        <translation>串口：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="81"/>
        <source>Baud:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="82"/>
        <source>Parity:</source>
        <translation>校验位：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="83"/>
        <source>Data bits:</source>
        <translation>数据位：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="84"/>
        <source>Stop bits:</source>
        <translation>停止位：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="85"/>
        <source>Slave id:</source>
        <translation>从站 ID：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="92"/>
        <location filename="../ui/device/connection_form.cpp" line="95"/>
        <source> ms</source>
        <translation> 毫秒</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="93"/>
        <source>How long to wait for the first byte of a reply, and for a TCP connection.</source>
        <translation>等待应答的第一个字节以及等待 TCP 连接的时长。</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="96"/>
        <source>How long to wait between two bytes of one reply.</source>
        <translation>同一应答中两个字节之间的最长等待时间。</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="105"/>
        <source> °/s</source>
        <translation> °/秒</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="106"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="107"/>
        <source>Of the robot program&apos;s maximal rotation speed.</source>
        <translation>占机器人程序最大旋转速度的百分比。</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="108"/>
        <location filename="../ui/device/connection_form.cpp" line="109"/>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="114"/>
        <source>Device:</source>
        <translation>设备：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="115"/>
        <source>Transport:</source>
        <translation>传输方式：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="119"/>
        <source>Response timeout:</source>
        <translation>应答超时：</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="120"/>
        <source>Byte timeout:</source>
        <translation>字节超时：</translation>
    </message>
</context>
<context>
    <name>multidir::ui::DeviceLink</name>
    <message>
        <location filename="../ui/device/device_link.cpp" line="30"/>
        <source>stall: the platform made no progress, so MultiDir stopped it</source>
        <translation>堵转：平台没有前进，MultiDir 已将其停止</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="31"/>
        <source>stall: the controller lost its position (following error)</source>
        <translation>堵转：控制器丢失了位置（跟随误差）</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="34"/>
        <source>heartbeat lost: the controller stopped because MultiDir went silent</source>
        <translation>心跳丢失：MultiDir 不再发送信号，控制器已停止</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="37"/>
        <source>a limit switch was hit</source>
        <translation>触发了限位开关</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="40"/>
        <source>the controller rejected a command (not homed, or beyond its own limits)</source>
        <translation>控制器拒绝了一条命令（未回零，或超出其自身限制）</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="43"/>
        <source>emergency stop: the power stage is off</source>
        <translation>急停：功率级已关闭</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="46"/>
        <source>unknown fault code %1</source>
        <translation>未知故障代码 %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="49"/>
        <source>; press Clear fault, then Enable and Home</source>
        <translation>；请按“清除故障”，然后按“使能”和“回零”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="55"/>
        <source>the robot program is not running: start it on the teach pendant</source>
        <translation>机器人程序未运行：请在示教器上启动它</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="57"/>
        <source>halted by an emergency stop: press Clear fault before moving again</source>
        <translation>已被急停停止：再次移动前请按“清除故障”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="61"/>
        <source>the target was beyond the robot program&apos;s limits; press Clear fault</source>
        <translation>目标超出了机器人程序的限制；请按“清除故障”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="63"/>
        <source>the robot stopped because MultiDir&apos;s heartbeat was lost; press Clear fault</source>
        <translation>由于 MultiDir 的心跳丢失，机器人已停止；请按“清除故障”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="65"/>
        <source>the robot program got an unknown command; press Clear fault</source>
        <translation>机器人程序收到了未知命令；请按“清除故障”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="67"/>
        <source>robot program fault code %1; press Clear fault</source>
        <translation>机器人程序故障代码 %1；请按“清除故障”</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="213"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>无法用这些设置连接：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="216"/>
        <source>Could not connect yet; MultiDir keeps trying. %1</source>
        <translation>尚未连接上；MultiDir 会继续尝试。%1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="244"/>
        <source>Enable</source>
        <translation>使能</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="247"/>
        <source>%1 does not apply to the robot arm: its program enables the arm; start it on the teach pendant.</source>
        <translation>%1 不适用于机械臂：机械臂由其程序使能；请在示教器上启动该程序。</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="257"/>
        <source>Home</source>
        <translation>回零</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="264"/>
        <source>Go to %1</source>
        <translation>前往 %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="267"/>
        <source>%1 refused: the robot arm takes a tilt and an azimuth.</source>
        <translation>%1 被拒绝：机械臂需要倾斜角和方位角。</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="274"/>
        <source>Go to tilt %1, azimuth %2</source>
        <translation>前往倾斜 %1，方位角 %2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="277"/>
        <source>%1 refused: the rotary platform takes one angle.</source>
        <translation>%1 被拒绝：旋转平台只需要一个角度。</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="284"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="290"/>
        <location filename="../ui/device/hardware_panel.cpp" line="621"/>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="296"/>
        <source>Clear fault</source>
        <translation>清除故障</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="314"/>
        <source>%1 refused: not connected; connect to the device first.</source>
        <translation>%1 被拒绝：未连接；请先连接设备。</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="326"/>
        <source>%1 refused, nothing was sent: %2</source>
        <translation>%1 被拒绝，未发送任何内容：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="328"/>
        <source>%1 cancelled by Stop, E-STOP or Disconnect: %2</source>
        <translation>%1 已被停止、急停或断开取消：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="330"/>
        <source>%1 failed at the device or on the link: %2</source>
        <translation>%1 在设备端或链路上失败：%2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ErrorText</name>
    <message>
        <location filename="../ui/common/error_text.cpp" line="18"/>
        <source>The file does not exist or cannot be read.</source>
        <translation>文件不存在或无法读取。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="20"/>
        <source>This file type is not supported: use STL, OBJ, OFF or PLY.</source>
        <translation>不支持此文件类型：请使用 STL、OBJ、OFF 或 PLY。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="22"/>
        <source>The file is damaged or does not follow its format.</source>
        <translation>文件已损坏或不符合其格式。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="24"/>
        <source>The model is larger than MultiDir accepts.</source>
        <translation>模型超出了 MultiDir 可接受的大小。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="26"/>
        <source>The file could not be written.</source>
        <translation>无法写入文件。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="28"/>
        <source>The file contains no triangles.</source>
        <translation>文件不包含任何三角形。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="30"/>
        <source>Some vertex coordinates are not numbers.</source>
        <translation>部分顶点坐标不是数值。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="32"/>
        <source>The surface is not a clean solid: some edges or vertices are shared by too many faces.</source>
        <translation>表面不是干净的实体：某些边或顶点被过多的面共用。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="35"/>
        <source>The surface has holes, so it does not enclose a solid. Close them in a mesh repair tool.</source>
        <translation>表面有孔洞，因此不能围成实体。请用网格修复工具将其封闭。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="38"/>
        <source>The faces of the surface point in inconsistent directions.</source>
        <translation>表面的面朝向不一致。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="40"/>
        <source>A setting is out of its allowed range.</source>
        <translation>某项设置超出了允许范围。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="42"/>
        <source>Cancelled.</source>
        <translation>已取消。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="44"/>
        <source>The device does not answer: check its power, cable or network.</source>
        <translation>设备没有应答：请检查其电源、线缆或网络。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="46"/>
        <source>The device reported an error.</source>
        <translation>设备报告了一个错误。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="48"/>
        <source>A program MultiDir runs (the slicer) is missing or failed.</source>
        <translation>MultiDir 调用的程序（切片软件）缺失或运行失败。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="50"/>
        <source>The produced G-code failed MultiDir&apos;s safety checks.</source>
        <translation>生成的 G 代码未通过 MultiDir 的安全检查。</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="54"/>
        <source>An internal error occurred: please report it with the model.</source>
        <translation>发生内部错误：请连同模型一起报告。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::HardwarePanel</name>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="71"/>
        <source>Disconnected</source>
        <translation>已断开</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="73"/>
        <source>Reconnecting…</source>
        <translation>正在重新连接…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="74"/>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="76"/>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="78"/>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="86"/>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="88"/>
        <source>turning the platform</source>
        <translation>正在转动平台</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="90"/>
        <source>settling</source>
        <translation>正在稳定</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="92"/>
        <source>printing</source>
        <translation>正在打印</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="94"/>
        <source>paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="96"/>
        <source>finished</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="98"/>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="100"/>
        <source>stopped by a device problem</source>
        <translation>因设备问题而停止</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="107"/>
        <source>angle %1</source>
        <translation>角度 %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="108"/>
        <location filename="../ui/device/hardware_panel.cpp" line="599"/>
        <source>tilt %1, azimuth %2</source>
        <translation>倾斜 %1，方位角 %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="117"/>
        <source>Clear fault, then Enable and Home</source>
        <translation>按“清除故障”，然后按“使能”和“回零”</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="118"/>
        <source>Clear fault; the robot program then takes moves again</source>
        <translation>按“清除故障”；之后机器人程序将重新接受运动指令</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="234"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="237"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="238"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="239"/>
        <source>Closes the link without commanding the device; its heartbeat watchdog stops it.</source>
        <translation>关闭链路而不向设备发送命令；设备的心跳看门狗会使其停止。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="253"/>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="264"/>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="266"/>
        <source>Enabled:</source>
        <translation>已使能：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="267"/>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="268"/>
        <source>Moving:</source>
        <translation>运动中：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="269"/>
        <source>Homed:</source>
        <translation>已回零：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="270"/>
        <source>Fault:</source>
        <translation>故障：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="271"/>
        <source>Heartbeat:</source>
        <translation>心跳：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="272"/>
        <source>Last problem:</source>
        <translation>最近的问题：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="277"/>
        <source>Controls</source>
        <translation>控制</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="278"/>
        <source>Enable</source>
        <translation>使能</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="278"/>
        <source>Switches the platform&apos;s drive on.</source>
        <translation>接通平台的驱动。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="279"/>
        <source>Home</source>
        <translation>回零</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="280"/>
        <source>Rotary platform: finds the home switch (0°). Robot arm: levels the platform (tilt 0°).</source>
        <translation>旋转平台：寻找原点开关（0°）。机械臂：将平台调平（倾斜 0°）。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="281"/>
        <source>Clear fault</source>
        <translation>清除故障</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="282"/>
        <source>Resets the device after a fault or an E-STOP; then enable and home again.</source>
        <translation>在故障或急停后复位设备；之后请重新使能并回零。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="286"/>
        <source>Tilt</source>
        <translation>倾斜</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="287"/>
        <source>Azimuth</source>
        <translation>方位角</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="288"/>
        <source>Jog −</source>
        <translation>点动 −</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="289"/>
        <source>Jog +</source>
        <translation>点动 +</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="293"/>
        <source>Angle:</source>
        <translation>角度：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="294"/>
        <source>Tilt:</source>
        <translation>倾斜：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="295"/>
        <source>Azimuth:</source>
        <translation>方位角：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="296"/>
        <source>Go to</source>
        <translation>前往</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="326"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="326"/>
        <source>Decelerates and stops; cancels queued commands.</source>
        <translation>减速并停止；取消排队中的命令。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="327"/>
        <location filename="../ui/device/hardware_panel.cpp" line="348"/>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="376"/>
        <source>Press when the region asked for has been printed (by hand: a region the connected printer prints goes on by itself).</source>
        <translation>所要求的区域打印完成后按此按钮（仅用于手动打印：由已连接的打印机打印的区域会自动继续）。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="495"/>
        <source>the platform</source>
        <translation>平台</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="496"/>
        <source>the printer</source>
        <translation>打印机</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="499"/>
        <source>E-STOP sent to %1. To go on: %2%3.</source>
        <translation>已向%1发送急停。如需继续：%2%3。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="500"/>
        <source> and </source>
        <translation>和</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="501"/>
        <source>; for the printer, Clear printer E-STOP and restart its firmware</source>
        <translation>；对于打印机，请按“清除打印机急停”并重启其固件</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="516"/>
        <source>Platform: stop confirmed by the device.</source>
        <translation>平台：设备已确认停止。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="517"/>
        <source>Platform: stop not confirmed yet; MultiDir keeps resending it.</source>
        <translation>平台：尚未确认停止；MultiDir 会持续重发。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="522"/>
        <source>Printer: emergency stop confirmed by the printer.</source>
        <translation>打印机：打印机已确认急停。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="523"/>
        <source>Printer: emergency stop not confirmed yet (%1); MultiDir keeps resending it.</source>
        <translation>打印机：尚未确认急停（%1）；MultiDir 会持续重发。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="639"/>
        <source>The print run stopped: %1. Fix the device (%2), then press Resume to retry this step, or Abort.</source>
        <translation>打印运行已停止：%1。请修复设备（%2），然后按“继续”重试此步骤，或按“中止”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="301"/>
        <source>Jog step:</source>
        <translation>点动步长：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="358"/>
        <source>Print run</source>
        <translation>打印运行</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="360"/>
        <location filename="../ui/device/hardware_panel.cpp" line="851"/>
        <source>Start run</source>
        <translation>开始运行</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="361"/>
        <source>Turns the platform to each region&apos;s orientation in printing order and asks for each region to be printed.</source>
        <translation>按打印顺序将平台转到每个区域的方向，并提示打印每个区域。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="375"/>
        <location filename="../ui/device/hardware_panel.cpp" line="419"/>
        <source>Region done</source>
        <translation>区域完成</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="378"/>
        <location filename="../ui/device/hardware_panel.cpp" line="420"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="379"/>
        <location filename="../ui/device/hardware_panel.cpp" line="421"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="380"/>
        <source>Continues a paused run, or retries the current step after a device problem.</source>
        <translation>继续已暂停的运行，或在设备出现问题后重试当前步骤。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="381"/>
        <location filename="../ui/device/hardware_panel.cpp" line="422"/>
        <location filename="../ui/device/hardware_panel.cpp" line="699"/>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="404"/>
        <source>Step:</source>
        <translation>步骤：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="405"/>
        <source>Elapsed:</source>
        <translation>已用时间：</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="441"/>
        <source>The link to %1 was lost at %2. The values below are not the device&apos;s any more; MultiDir keeps trying to reconnect.</source>
        <translation>与 %1 的链路于 %2 中断。下方数值已不再反映设备的状态；MultiDir 会继续尝试重新连接。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="445"/>
        <source>The print run is paused: a region being printed may finish, no new region starts. Press Resume once the link is back.</source>
        <translation>打印运行已暂停：正在打印的区域可以完成，但不会开始新的区域。链路恢复后请按“继续”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="448"/>
        <source>%1 does not answer: %2</source>
        <translation>%1 没有应答：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="451"/>
        <source>The link is back. The print run is still paused since the link was lost: check the platform, then press Resume.</source>
        <translation>链路已恢复。由于链路曾中断，打印运行仍处于暂停状态：请检查平台，然后按“继续”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="558"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>无法用这些设置连接：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="563"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="572"/>
        <source>Disconnected.</source>
        <translation>已断开。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="582"/>
        <source>Not reachable; MultiDir keeps trying…</source>
        <translation>无法访问；MultiDir 会继续尝试…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="584"/>
        <source>Link lost at %1; reconnecting…</source>
        <translation>链路于 %1 中断；正在重新连接…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="594"/>
        <source>no: press Enable</source>
        <translation>否：请按“使能”</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="595"/>
        <source>%1 (target %2)</source>
        <translation>%1（目标 %2）</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <source>homing</source>
        <translation>正在回零</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="594"/>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <location filename="../ui/device/hardware_panel.cpp" line="597"/>
        <location filename="../ui/device/hardware_panel.cpp" line="600"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <location filename="../ui/device/hardware_panel.cpp" line="597"/>
        <location filename="../ui/device/hardware_panel.cpp" line="600"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="601"/>
        <source>not needed (robot arm)</source>
        <translation>不需要（机械臂）</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="603"/>
        <location filename="../ui/device/hardware_panel.cpp" line="608"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="622"/>
        <source>%1: sent to the device. To go on: %2.</source>
        <translation>%1：已发送到设备。如需继续：%2。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="624"/>
        <source>%1: sent to the device.</source>
        <translation>%1：已发送到设备。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="630"/>
        <source>Connected to %1.</source>
        <translation>已连接到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="643"/>
        <source>The print run is finished: every region was printed.</source>
        <translation>打印运行已完成：所有区域均已打印。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="645"/>
        <source>The print run was aborted.</source>
        <translation>打印运行已中止。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="662"/>
        <source>Region %1 is printed by %2 (%3); the run goes on when the printer reports it complete.</source>
        <translation>区域 %1 正由 %2 打印（%3）；打印机报告完成后运行将继续。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="667"/>
        <source>Print region %1 (file %2), then press Region done.</source>
        <translation>请打印区域 %1（文件 %2），然后按“区域完成”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="813"/>
        <source>Start run refused: not connected; connect to the device first.</source>
        <translation>开始运行被拒绝：未连接；请先连接设备。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="821"/>
        <location filename="../ui/device/hardware_panel.cpp" line="828"/>
        <location filename="../ui/device/hardware_panel.cpp" line="850"/>
        <source>Start run refused: %1</source>
        <translation>开始运行被拒绝：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="854"/>
        <source>The plan is not sliced: each region is printed by hand (Region done). Slice the plan to have the printer print them.</source>
        <translation>方案尚未切片：每个区域需手动打印（“区域完成”）。请对方案切片，以便由打印机打印各区域。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="856"/>
        <source>The sliced job has %1 steps, the plan %2 regions: each region is printed by hand (Region done). Slice the plan again.</source>
        <translation>切片作业有 %1 个步骤，方案有 %2 个区域：每个区域需手动打印（“区域完成”）。请重新对方案切片。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="864"/>
        <source>%1 refused: %2</source>
        <translation>%1 被拒绝：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="884"/>
        <source>Limits: %1 to %2 in steps of %3</source>
        <translation>限制：%1 至 %2，步长 %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="886"/>
        <source>Limits: tilt up to %1, %n forbidden cone(s)</source>
        <translation>
            <numerusform>限制：倾斜最多 %1，%n 个禁止锥</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="889"/>
        <source> (machine profile)</source>
        <translation>（机器配置）</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="891"/>
        <source> (defaults: the machine profile is for a %1 machine)</source>
        <translation>（默认值：该机器配置适用于 %1 机器）</translation>
    </message>
    <message>
        <source> (defaults: no machine profile)</source>
        <translation type="vanished">（默认值：无机器配置）</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="893"/>
        <source>; a changed profile applies at the next Connect</source>
        <translation>；更改后的配置在下次连接时生效</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="919"/>
        <source>Emergency stop: cuts the platform&apos;s power stage at once. Afterwards: %1.</source>
        <translation>急停：立即切断平台的功率级。之后：%1。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="921"/>
        <source>Emergency stop: halts the robot program at maximal deceleration. Afterwards: %1.</source>
        <translation>急停：以最大减速度停止机器人程序。之后：%1。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="926"/>
        <source>Resets the platform after a fault or an E-STOP; then Enable and Home again.</source>
        <translation>在故障或急停后复位平台；之后请重新“使能”并“回零”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="927"/>
        <source>Resets the robot program after a fault or an E-STOP; it then takes moves again.</source>
        <translation>在故障或急停后复位机器人程序；之后它将重新接受运动指令。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="929"/>
        <source>Finds the home switch (0°); the drive must be enabled.</source>
        <translation>寻找原点开关（0°）；驱动必须已使能。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="930"/>
        <source>Levels the platform (tilt 0°).</source>
        <translation>将平台调平（倾斜 0°）。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="979"/>
        <source>unknown since %1</source>
        <translation>自 %1 起未知</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="981"/>
        <source>not seen yet</source>
        <translation>尚未收到</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="984"/>
        <source>%1 s ago</source>
        <translation>%1 秒前</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="993"/>
        <source>No plan: run a search or open a plan first.</source>
        <translation>无方案：请先运行搜索或打开方案。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="994"/>
        <source>Plan with %n region(s).</source>
        <translation>
            <numerusform>方案包含 %n 个区域。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="996"/>
        <source>Sliced: a connected printer prints each region&apos;s G-code.</source>
        <translation>已切片：已连接的打印机将打印每个区域的 G 代码。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="1004"/>
        <source>all %n region(s) printed: finished</source>
        <translation>
            <numerusform>全部 %n 个区域已打印：完成</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1006"/>
        <source>%1 of %2: %3</source>
        <translation>%1 / %2：%3</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1008"/>
        <source> (%1, %2)</source>
        <translation>（%1，%2）</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1009"/>
        <source>; pausing after this region</source>
        <translation>；此区域完成后暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="386"/>
        <location filename="../ui/device/hardware_panel.cpp" line="798"/>
        <source>Restart step</source>
        <translation>重新开始步骤</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="387"/>
        <source>Prints the current step again from the start of its G-code, once you have cleared the platform of what the interrupted print left.</source>
        <translation>在您清除平台上中断的打印留下的部分后，从其 G 代码的开头重新打印当前步骤。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="720"/>
        <source>Start Run</source>
        <translation>开始运行</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="721"/>
        <source>The last run of this plan was aborted at step %1 of %2.</source>
        <translation>此方案的上次运行在第 %1 步（共 %2 步）时中止。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="727"/>
        <source>Steps 1 to %1 were printed. Before the platform moves, make sure it is clear: take off what step %2 left half printed and anything in the platform&apos;s way.</source>
        <translation>步骤 1 至 %1 已打印。平台移动之前，请确保其周围畅通：取下步骤 %2 打印了一半的部分以及挡住平台的任何物体。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="731"/>
        <source>Before the platform moves, make sure it is clear: take off what step 1 left half printed and anything in the platform&apos;s way.</source>
        <translation>平台移动之前，请确保其周围畅通：取下步骤 1 打印了一半的部分以及挡住平台的任何物体。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="735"/>
        <source>Platform Clear: &amp;Resume from Step %1</source>
        <translation>平台已清空：从步骤 %1 继续(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="738"/>
        <source>Platform Clear: &amp;Start from Step 1</source>
        <translation>平台已清空：从步骤 1 开始(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="751"/>
        <source>Start run refused: the plan changed since the question was asked; press Start run again.</source>
        <translation>“开始运行”被拒绝：提问后方案已更改；请再次按“开始运行”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="764"/>
        <source>%1 has no job of step %2 any more: it may have restarted, so there is nothing to resume. Restart step prints step %2 again from its start, once you have cleared the platform of what the interrupted print left. Or finish the region by hand and press Region done, or Abort.</source>
        <translation>%1 已没有步骤 %2 的任务：它可能已重启，因此没有可继续的内容。清除平台上中断的打印留下的部分后，“重新开始步骤”会从头重新打印步骤 %2。或者手动完成该区域并按“区域完成”，或按“中止”。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="770"/>
        <source>Restart Step %1</source>
        <translation>重新开始步骤 %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="780"/>
        <source>Restart Step</source>
        <translation>重新开始步骤</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="781"/>
        <source>Print step %1 again from its start?</source>
        <translation>从头重新打印步骤 %1？</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="783"/>
        <source>The printer lost the job of step %1 part way. Before it prints the step again, take off what the interrupted print left of region %1 (the regions printed before it stay) and make sure the nozzle&apos;s way is clear.</source>
        <translation>打印机在步骤 %1 中途丢失了任务。在重新打印该步骤之前，请取下中断的打印留下的区域 %1 部分（之前打印的区域保留），并确保喷嘴的路径畅通。</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="787"/>
        <source>Platform Clear: &amp;Restart Step %1</source>
        <translation>平台已清空：重新开始步骤 %1(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="497"/>
        <source>the robot cell</source>
        <translation>机器人单元</translation>
    </message>
</context>
<context>
    <name>multidir::ui::JgChart</name>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="27"/>
        <source>Level</source>
        <translation>层级</translation>
    </message>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="32"/>
        <source>Best J_G (mm²)</source>
        <translation>最佳 J_G (mm²)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::JobTimeline</name>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Region</source>
        <translation>区域</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Started</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Ended</source>
        <translation>结束时间</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="133"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="135"/>
        <source>moving</source>
        <translation>正在移动</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="137"/>
        <source>settling</source>
        <translation>正在稳定</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="139"/>
        <source>printing</source>
        <translation>正在打印</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="141"/>
        <source>done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="143"/>
        <source>paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="145"/>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="147"/>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="157"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MachineKind</name>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="9"/>
        <source>3-DOF</source>
        <translation>3-DOF</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="11"/>
        <source>rotary platform (4-DOF)</source>
        <translation>旋转平台(4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="13"/>
        <source>tilting (5-DOF)</source>
        <translation>倾斜式(5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="15"/>
        <source>printed apart</source>
        <translation>分开打印</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MachinePanel</name>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="32"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="48"/>
        <source>3-DOF: fixed printing direction</source>
        <translation>3 自由度：固定打印方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="49"/>
        <source>4-DOF: rotary platform</source>
        <translation>4 自由度：旋转平台</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="50"/>
        <source>5-DOF: tilting robot arm</source>
        <translation>5 自由度：倾斜机械臂</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="57"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>旋转平台（4 自由度）</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="60"/>
        <source>The axis the platform turns about, as x,y,z or x, -y, +z; it must lie in the platform plane (perpendicular to up)</source>
        <translation>平台绕其旋转的轴，格式为 x,y,z 或 x、-y、+z；它必须位于平台平面内（垂直于向上方向）</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="62"/>
        <source>Pick on platform</source>
        <translation>在平台上选取</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="65"/>
        <source>Click two points on the platform in the 3D view: the axis runs from the first to the second. Esc or this button again cancels.</source>
        <translation>在 3D 视图中点击平台上的两个点：轴从第一个点指向第二个点。按 Esc 或再次点击此按钮可取消。</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="70"/>
        <source>The stepper&apos;s resolution: only multiples of this angle can be reached</source>
        <translation>步进电机的分辨率：只能到达该角度的整数倍</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="72"/>
        <source>Rotation axis:</source>
        <translation>旋转轴：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="74"/>
        <source>Minimal angle:</source>
        <translation>最小角度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="75"/>
        <source>Maximal angle:</source>
        <translation>最大角度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="76"/>
        <source>Angle step:</source>
        <translation>角度步长：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="78"/>
        <source>Tilting arm (5-DOF)</source>
        <translation>倾斜机械臂（5 自由度）</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="80"/>
        <source>How far the arm can tilt the platform away from up</source>
        <translation>机械臂能将平台从向上方向倾斜的最大角度</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="82"/>
        <source>Tilt limit:</source>
        <translation>倾斜极限：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="88"/>
        <source> mm</source>
        <translation> 毫米</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="89"/>
        <source>model footprint</source>
        <translation>模型底面</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="91"/>
        <source>Radius of the platform disc that no clipping plane may cut; 0 uses the model&apos;s footprint plus a margin</source>
        <translation>任何切割平面都不得穿过的平台圆盘半径；0 表示使用模型底面加上边距</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="101"/>
        <source>Machine:</source>
        <translation>机器：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="102"/>
        <source>Platform radius:</source>
        <translation>平台半径：</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="212"/>
        <source>The rotation axis &quot;%1&quot; cannot be read: type three numbers x,y,z or an axis such as x or -y.</source>
        <translation>无法识别旋转轴“%1”：请输入三个数 x,y,z，或 x、-y 这样的坐标轴。</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="217"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="51"/>
        <source>5-DOF: robot arm under a fixed extruder</source>
        <translation>5 自由度：固定挤出机下的机械臂</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="54"/>
        <source>Apart (plain printer, parts joined by dowels)</source>
        <translation>分开打印（普通打印机，零件用定位销连接）</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="95"/>
        <source>MultiDir Studio</source>
        <translation>MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="126"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="127"/>
        <source>&amp;Open...</source>
        <translation>打开(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="145"/>
        <source>Show a plan saved earlier (a folder with plan.json)</source>
        <translation>显示之前保存的方案（包含 plan.json 的文件夹）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="146"/>
        <source>&amp;Export plan...</source>
        <translation>导出方案(&amp;E)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="148"/>
        <source>Save the plan shown: plan.json and one STL per region</source>
        <translation>保存当前方案：plan.json 以及每个区域一个 STL 文件</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="159"/>
        <source>&amp;Load machine profile...</source>
        <translation>加载机器配置(&amp;L)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="164"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="168"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="169"/>
        <source>&amp;Fit to View</source>
        <translation>适应视图(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="171"/>
        <source>Show the &amp;model (hide the plan)</source>
        <translation>显示模型(&amp;M)（隐藏方案）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="179"/>
        <location filename="../ui/main_window.cpp" line="747"/>
        <source>&amp;Search</source>
        <translation>搜索(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="180"/>
        <source>&amp;Run</source>
        <translation>运行(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="184"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="256"/>
        <source>Overhangs</source>
        <translation>悬垂</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="257"/>
        <source>Machine</source>
        <translation>机器</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="258"/>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="267"/>
        <source>Plan</source>
        <translation>方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="322"/>
        <source>Hardware</source>
        <translation>硬件</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="360"/>
        <source>Printing direction</source>
        <translation>打印方向</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="363"/>
        <source>Up:</source>
        <translation>向上：</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="370"/>
        <source>The direction the model is printed along: the platform is below, overhangs are measured against it</source>
        <translation>模型的打印方向：平台位于下方，悬垂相对于该方向计算</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="375"/>
        <source>+X</source>
        <translation>+X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="375"/>
        <source>-X</source>
        <translation>-X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="376"/>
        <source>+Y</source>
        <translation>+Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="376"/>
        <source>-Y</source>
        <translation>-Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="377"/>
        <source>+Z</source>
        <translation>+Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="377"/>
        <source>-Z</source>
        <translation>-Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="130"/>
        <source>Open a mesh file (STL, OBJ, OFF or PLY) or a MultiDir project</source>
        <translation>打开网格文件（STL、OBJ、OFF 或 PLY）或 MultiDir 项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>Save the 3D view as shown to a PNG or JPEG file</source>
        <translation>将当前显示的 3D 视图保存为 PNG 或 JPEG 文件</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="161"/>
        <source>Save machine pro&amp;file...</source>
        <translation>保存机器配置(&amp;F)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="173"/>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="197"/>
        <source>S&amp;lice the plan...</source>
        <translation>切片此方案(&amp;L)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="200"/>
        <source>Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)</source>
        <translation>将所示方案的每一步连同支撑切片为 G 代码(PrusaSlicer)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="214"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="215"/>
        <source>&amp;About MultiDir Studio</source>
        <translation>关于 MultiDir Studio(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="222"/>
        <source>About MultiDir Studio</source>
        <translation>关于 MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="223"/>
        <source>MultiDir Studio %1</source>
        <translation>MultiDir Studio %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="225"/>
        <source>Plans multi-directional 3D prints: cuts a model by planes into regions, each printed along its own direction, and drives the machine that prints them.

Qt %1</source>
        <translation>规划多方向 3D 打印：用平面将模型切割成多个区域，每个区域沿各自的方向打印，并驱动打印它们的机器。

Qt %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="324"/>
        <source>Emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="442"/>
        <source>The pose search was stopped; its result is dropped.</source>
        <translation>姿态搜索已停止；其结果已丢弃。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="448"/>
        <source>The search was stopped; its result is dropped.</source>
        <translation>搜索已停止；其结果已丢弃。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="462"/>
        <source>Open Model or Project</source>
        <translation>打开模型或项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="463"/>
        <source>Meshes and projects (*.stl *.obj *.off *.ply *.multidir);;Meshes (*.stl *.obj *.off *.ply);;MultiDir projects (*.multidir);;All files (*)</source>
        <translation>网格和项目 (*.stl *.obj *.off *.ply *.multidir);;网格 (*.stl *.obj *.off *.ply);;MultiDir 项目 (*.multidir);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="500"/>
        <source>%1, %2, %3</source>
        <translation>%1, %2, %3</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="507"/>
        <location filename="../ui/main_window.cpp" line="513"/>
        <source>Pose: %1</source>
        <translation>姿态：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="508"/>
        <source>Custom (%1, %2, %3)</source>
        <translation>自定义（%1, %2, %3）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>%1 - MultiDir Studio</source>
        <translation>%1 - MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="583"/>
        <source>Repaired on load: %1</source>
        <translation>加载时已修复：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="597"/>
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="601"/>
        <source>Could not open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="605"/>
        <source>%1 is still open.</source>
        <translation>%1 仍处于打开状态。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="628"/>
        <location filename="../ui/main_window.cpp" line="645"/>
        <source>No model</source>
        <translation>无模型</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="638"/>
        <source>Triangles: %1</source>
        <translation>三角形：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="639"/>
        <source>Volume: %1 mm³</source>
        <translation>体积：%1 mm³</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="653"/>
        <source>Risky area unavailable</source>
        <translation>风险面积不可用</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="661"/>
        <source>Risky area (%1 up): %2 mm²</source>
        <translation>风险面积（%1 向上）：%2 mm²</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="663"/>
        <source>Area of the faces that overhang by more than %1° for this up direction</source>
        <translation>在此向上方向下悬垂超过 %1° 的面的面积</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="682"/>
        <location filename="../ui/main_window.cpp" line="705"/>
        <location filename="../ui/main_window_pose.cpp" line="38"/>
        <location filename="../ui/main_window_pose.cpp" line="55"/>
        <source>Open a model first.</source>
        <translation>请先打开一个模型。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="684"/>
        <location filename="../ui/main_window_pose.cpp" line="40"/>
        <source>Fix the machine first: %1</source>
        <translation>请先修正机器设置：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="686"/>
        <location filename="../ui/main_window.cpp" line="704"/>
        <source>A pose search is running: wait for it or cancel it.</source>
        <translation>姿态搜索正在运行：请等待其完成或将其取消。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="703"/>
        <source>A search is already running.</source>
        <translation>已有搜索正在运行。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="710"/>
        <location filename="../ui/main_window_pose.cpp" line="63"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="714"/>
        <source>Cannot search: %1</source>
        <translation>无法搜索：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="715"/>
        <source>Cannot search.</source>
        <translation>无法搜索。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="729"/>
        <source>Searching %1...</source>
        <translation>正在搜索 %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="764"/>
        <source>Cancelling the search...</source>
        <translation>正在取消搜索...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="777"/>
        <source>The search result was dropped: the model or its up direction changed.</source>
        <translation>搜索结果已丢弃：模型或其向上方向已改变。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="792"/>
        <source>Search cancelled: showing the best plan found so far.</source>
        <translation>搜索已取消：显示目前找到的最佳方案。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="793"/>
        <source>Search finished.</source>
        <translation>搜索完成。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="813"/>
        <source>Search failed: %1</source>
        <translation>搜索失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="849"/>
        <source>Growing supports for the plan...</source>
        <translation>正在为方案生成支撑...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="861"/>
        <source>Supports grown for the plan.</source>
        <translation>已为方案生成支撑。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="931"/>
        <source>There is no plan to export: run a search first.</source>
        <translation>没有可导出的方案：请先运行搜索。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="934"/>
        <source>The supports of this plan are still being grown: export it again when the status bar says they are ready.</source>
        <translation>此方案的支撑仍在生成中：请在状态栏提示支撑已就绪后重新导出。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="938"/>
        <source>Could not create the folder %1: check that its parent exists and can be written.</source>
        <translation>无法创建文件夹 %1：请检查其上级文件夹是否存在且可写入。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="968"/>
        <source>Could not export the plan to %1: %2 (%3)</source>
        <translation>无法将方案导出到 %1：%2（%3）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="974"/>
        <source>Plan exported to %1 without supports although %2 mm² of risky area remains: %3</source>
        <translation>方案已导出到 %1，但未包含支撑，尽管仍剩余 %2 mm² 风险面积：%3</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="976"/>
        <source>no supports were grown for it.</source>
        <translation>未为其生成支撑。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="981"/>
        <source>Plan exported to %1.</source>
        <translation>方案已导出到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="988"/>
        <source>Could not open the plan %1: %2 (%3)</source>
        <translation>无法打开方案 %1：%2（%3）</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1035"/>
        <source>Machine profile saved to %1.</source>
        <translation>机器配置已保存到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1047"/>
        <source>Machine profile %1 loaded.</source>
        <translation>已加载机器配置 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1056"/>
        <source>Export Plan to Folder</source>
        <translation>将方案导出到文件夹</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1056"/>
        <source>-plan</source>
        <translation>-方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1057"/>
        <source>Plan folders (*)</source>
        <translation>方案文件夹 (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1063"/>
        <location filename="../ui/main_window.cpp" line="1065"/>
        <source>Export Plan</source>
        <translation>导出方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1076"/>
        <source>Screenshot saved to %1.</source>
        <translation>截图已保存到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1081"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1082"/>
        <source>JPEG images (*.jpg *.jpeg)</source>
        <translation>JPEG 图像 (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1085"/>
        <location filename="../ui/main_window.cpp" line="1093"/>
        <source>Export Screenshot</source>
        <translation>导出截图</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1098"/>
        <source>Open Plan Folder</source>
        <translation>打开方案文件夹</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="433"/>
        <source>Open Plan</source>
        <translation>打开方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="133"/>
        <source>Sa&amp;mples</source>
        <translation>示例(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="143"/>
        <source>Open pla&amp;n...</source>
        <translation>打开方案(&amp;N)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="150"/>
        <source>Export &amp;G-code...</source>
        <translation>导出 G 代码(&amp;G)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="152"/>
        <source>Save the sliced plan&apos;s G-code (step-NN.gcode, job.gcode) and its print job</source>
        <translation>保存已切片方案的 G 代码（step-NN.gcode、job.gcode）及其打印作业</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Export Screens&amp;hot...</source>
        <translation>导出截图(&amp;H)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1104"/>
        <location filename="../ui/main_window.cpp" line="1110"/>
        <source>Save Machine Profile</source>
        <translation>保存机器配置</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1106"/>
        <source>Machine profiles (*.json)</source>
        <translation>机器配置 (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1114"/>
        <location filename="../ui/main_window.cpp" line="1121"/>
        <source>Load Machine Profile</source>
        <translation>加载机器配置</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1116"/>
        <source>Machine profiles (*.json);;All files (*)</source>
        <translation>机器配置 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1134"/>
        <source>Loading %1...</source>
        <translation>正在加载 %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="22"/>
        <source>Edit plan</source>
        <translation>编辑方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="60"/>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="62"/>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="65"/>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="42"/>
        <location filename="../ui/main_window_pose.cpp" line="54"/>
        <source>A search is running: wait for it or cancel it.</source>
        <translation>搜索正在运行：请等待其完成或将其取消。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="53"/>
        <source>A pose search is already running.</source>
        <translation>已有姿态搜索正在运行。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="56"/>
        <source>This plan was opened without its model: open the model.</source>
        <translation>此方案是在没有其模型的情况下打开的：请打开模型。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="67"/>
        <source>Cannot find the best pose: %1</source>
        <translation>无法查找最佳姿态：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="68"/>
        <source>Cannot find the best pose.</source>
        <translation>无法查找最佳姿态。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="77"/>
        <source>Finding the best pose for %1...</source>
        <translation>正在为 %1 查找最佳姿态...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="85"/>
        <source>Cancelling the pose search...</source>
        <translation>正在取消姿态搜索...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="98"/>
        <source>The pose search result was dropped: the model or its up direction changed.</source>
        <translation>姿态搜索结果已丢弃：模型或其向上方向已改变。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="108"/>
        <source>Pose search cancelled: the poses that finished are listed; the plan shown is unchanged.</source>
        <translation>姿态搜索已取消：已完成的姿态已列出；当前显示的方案未改变。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="112"/>
        <source>Best pose found.</source>
        <translation>已找到最佳姿态。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="122"/>
        <source>Pose search cancelled before any pose finished: the plan shown is unchanged.</source>
        <translation>姿态搜索在任何姿态完成之前被取消：当前显示的方案未改变。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="124"/>
        <source>Pose search failed: %1</source>
        <translation>姿态搜索失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="140"/>
        <source>Showing pose %1 (up %2, %3, %4): the project is unchanged. &quot;Use this pose&quot; makes it the model&apos;s up; &quot;Show current up&quot; goes back.</source>
        <translation>正在显示姿态 %1（向上方向 %2, %3, %4）：项目未改变。“使用此姿态”将其设为模型的向上方向；“显示当前向上方向”可返回。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="187"/>
        <source>This pose belongs to another model: find the best pose again.</source>
        <translation>此姿态属于另一个模型：请重新查找最佳姿态。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="203"/>
        <source>The model now stands on the best pose; its plan is shown.</source>
        <translation>模型现已按最佳姿态摆放；显示其方案。</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="206"/>
        <source>The model now stands on pose %1; searching its plan...</source>
        <translation>模型现已按姿态 %1 摆放；正在搜索其方案...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="743"/>
        <source>Replace the Edited Plan</source>
        <translation>替换已编辑的方案</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="744"/>
        <source>The plan shown has edits that are not saved.</source>
        <translation>显示的方案有未保存的编辑。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="746"/>
        <source>A new search replaces it; Edit &gt; Undo brings it back. Search now?</source>
        <translation>新的搜索将替换它；“编辑 &gt; 撤销”可将其恢复。现在搜索吗？</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="784"/>
        <source>Search cancelled: its best plan so far (J_G %1 mm²) is worse than the plan shown (J_G %2 mm²), which is kept.</source>
        <translation>搜索已取消：其目前最佳方案（J_G %1 mm²）比显示的方案（J_G %2 mm²）差，保留显示的方案。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="904"/>
        <source>Print Run Under Way</source>
        <translation>打印运行进行中</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="905"/>
        <source>A print run is under way: step %1.</source>
        <translation>打印运行正在进行：步骤 %1。</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="908"/>
        <source>Quitting stops the platform and the printer first: the run is aborted (Start run offers to resume it from the step it stopped at). Stop the devices and quit?</source>
        <translation>退出会先停止平台和打印机：运行将被中止（“开始运行”可以从其停止的步骤继续）。停止设备并退出吗？</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="910"/>
        <source>S&amp;top the Devices and Quit</source>
        <translation>停止设备并退出(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="203"/>
        <source>Print &amp;apart...</source>
        <translation>分开打印(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="209"/>
        <source>Print the plan shown on an ordinary printer: every region a part, joined by dowels</source>
        <translation>在普通打印机上打印所示方案：每个区域为一个零件，用定位销连接</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="272"/>
        <source>Print apart</source>
        <translation>分开打印</translation>
    </message>
    <message>
        <location filename="../ui/main_window_cell.cpp" line="23"/>
        <source>Cell view</source>
        <translation>单元视图</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MeshViewerWidget</name>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="421"/>
        <source>Open a model (%1) or File &gt; Samples</source>
        <translation>打开模型(%1)或 文件 &gt; 示例</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="629"/>
        <source>%1, %2, %3 mm</source>
        <translation>%1, %2, %3 mm</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="633"/>
        <source>A: %1</source>
        <translation>A:%1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="635"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="636"/>
        <source>B: %1</source>
        <translation>B:%1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="637"/>
        <source>Distance: %1</source>
        <translation>距离:%1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="640"/>
        <source>Click a second point on the model (Esc ends measuring)</source>
        <translation>在模型上点击第二个点(Esc 结束测量)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="29"/>
        <source>&amp;Front</source>
        <translation>前视(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="29"/>
        <source>Look at the model&apos;s front</source>
        <translation>从前方查看模型</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="31"/>
        <source>&amp;Back</source>
        <translation>后视(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="31"/>
        <source>Look at the model&apos;s back</source>
        <translation>从后方查看模型</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="33"/>
        <source>&amp;Left</source>
        <translation>左视(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="33"/>
        <source>Look at the model&apos;s left side</source>
        <translation>查看模型左侧</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="35"/>
        <source>&amp;Right</source>
        <translation>右视(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="36"/>
        <source>Look at the model&apos;s right side</source>
        <translation>查看模型右侧</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="37"/>
        <source>&amp;Top</source>
        <translation>俯视(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="38"/>
        <source>Look down the printing direction (Up)</source>
        <translation>沿打印方向(向上)向下看</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="39"/>
        <source>Botto&amp;m</source>
        <translation>仰视(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="40"/>
        <source>Look up at the model from below the platform</source>
        <translation>从平台下方向上查看模型</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="41"/>
        <source>&amp;Isometric</source>
        <translation>等轴测(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="42"/>
        <source>Look at the front, the right and the top equally</source>
        <translation>同等地查看前面、右面和顶面</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="45"/>
        <source>&amp;Standard views</source>
        <translation>标准视图(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="59"/>
        <source>&amp;Orthographic</source>
        <translation>正交投影(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="64"/>
        <source>Parallel projection: equal lengths look equal wherever they are (5)</source>
        <translation>平行投影:等长的线段无论在何处看起来都等长(5)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="68"/>
        <source>M&amp;easure distance</source>
        <translation>测量距离(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="73"/>
        <source>Click two points on the model: their coordinates and the distance between them (M; Esc ends)</source>
        <translation>在模型上点击两个点:显示它们的坐标及其间距离(M;Esc 结束)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ModelLoader</name>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="51"/>
        <source>Not enough memory to load this model.</source>
        <translation>内存不足，无法加载此模型。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="54"/>
        <location filename="../ui/jobs/model_loader.cpp" line="58"/>
        <source>Unexpected error while loading.</source>
        <translation>加载时发生意外错误。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::OverhangPanel</name>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="29"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="32"/>
        <source>Maximal self-supporting angle: faces that lean over by more than this from the printing direction need support</source>
        <translation>最大自支撑角度：相对打印方向倾斜超过此角度的面需要支撑</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="65"/>
        <source>Risky faces (need support when printed along the up direction)</source>
        <translation>风险面（沿向上方向打印时需要支撑）</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="68"/>
        <source>Max. overhang angle α:</source>
        <translation>最大悬垂角 α：</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="69"/>
        <source>Risky area:</source>
        <translation>风险面积：</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="70"/>
        <source>Risky faces:</source>
        <translation>风险面：</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="75"/>
        <source>No model</source>
        <translation>无模型</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="83"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="85"/>
        <source>%1 of %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="90"/>
        <source>unavailable</source>
        <translation>不可用</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PictureFile</name>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="32"/>
        <source>Could not save %1: there is no picture to save.</source>
        <translation>无法保存 %1：没有可保存的图像。</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="35"/>
        <source>Could not save %1: give the file name the extension .png or .jpg.</source>
        <translation>无法保存 %1：请给文件名加上扩展名 .png 或 .jpg。</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="42"/>
        <source>Could not save %1: the file cannot be written there; check that its folder exists and may be written to.</source>
        <translation>无法保存 %1：无法在该位置写入文件；请检查其所在文件夹是否存在且可写入。</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="45"/>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PlanPanel</name>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="66"/>
        <location filename="../ui/panels/plan_panel.cpp" line="200"/>
        <source>No plan yet: run a search or open a plan.</source>
        <translation>尚无方案：请运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Region</source>
        <translation>区域</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Volume (mm³)</source>
        <translation>体积 (mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Risky (mm²)</source>
        <translation>风险 (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Machine angles</source>
        <translation>机器角度</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Supports (mm³)</source>
        <translation>支撑 (mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="84"/>
        <source>Printing directions</source>
        <translation>打印方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="87"/>
        <source>Clipping planes</source>
        <translation>切割平面</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="89"/>
        <source>Supports</source>
        <translation>支撑</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="92"/>
        <source>The tree supports grown for the risky area the plan leaves, in one colour</source>
        <translation>为方案剩余的风险面积生成的树状支撑，以单一颜色显示</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="93"/>
        <source>Turn the view as the machine turns the part</source>
        <translation>随机器转动零件而旋转视图</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="98"/>
        <source>Moves the regions apart along their printing directions</source>
        <translation>沿各自打印方向将区域分开</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="105"/>
        <source>Previous region</source>
        <translation>上一个区域</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="108"/>
        <source>Next region</source>
        <translation>下一个区域</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="117"/>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="120"/>
        <source>Exploded view:</source>
        <translation>爆炸视图：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="121"/>
        <source>Printed up to:</source>
        <translation>打印到：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="159"/>
        <source>none (fixed)</source>
        <translation>无（固定）</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="161"/>
        <source>rotary %1°</source>
        <translation>旋转 %1°</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="165"/>
        <source>tilt %1°, azimuth %2°</source>
        <translation>倾斜 %1°，方位角 %2°</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="173"/>
        <location filename="../ui/panels/plan_panel.cpp" line="176"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="174"/>
        <source>No supports were grown for this plan</source>
        <translation>未为此方案生成支撑</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/plan_panel.cpp" line="178"/>
        <source>%n region(s); J_G %1 mm² before, %2 mm² after.</source>
        <translation>
            <numerusform>%n 个区域；J_G 之前 %1 mm²，之后 %2 mm²。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="233"/>
        <source>of %1</source>
        <translation>共 %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="50"/>
        <source>1 contact on risky faces</source>
        <translation>风险面上 1 个接触点</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="51"/>
        <source>%1 contacts on risky faces</source>
        <translation>风险面上 %1 个接触点</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="53"/>
        <source>1 lowest point</source>
        <translation>1 个最低点</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="54"/>
        <source>%1 lowest points</source>
        <translation>%1 个最低点</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="56"/>
        <source>%1 mm of downward edges</source>
        <translation>%1 mm 朝下的边</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="58"/>
        <source>struts of later regions (%1 mm³)</source>
        <translation>后续区域的支柱（%1 mm³）</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Supports hold up</source>
        <translation>支撑所承托</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="75"/>
        <source>Risky faces are the area J_G counts. Lowest points and downward edges have no area but still print in air; struts of regions printed later go on through this region&apos;s space.</source>
        <translation>风险面是 J_G 计入的面积。最低点和朝下的边没有面积，但仍会悬空打印；后续打印区域的支柱会穿过此区域的空间。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PlaneEditPanel</name>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Plane</source>
        <translation>平面</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Normal</source>
        <translation>法向</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Offset (mm)</source>
        <translation>偏移 (mm)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="91"/>
        <source>Planes are numbered in printing order, like the regions: plane k is the base of region k + 1</source>
        <translation>平面与区域一样按打印顺序编号：平面 k 是区域 k + 1 的底面</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="105"/>
        <source> mm</source>
        <translation> 毫米</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="107"/>
        <source>Distance of the plane from the origin along its normal</source>
        <translation>平面沿其法向到原点的距离</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="110"/>
        <source>Moves the plane along its normal across what is left of the model</source>
        <translation>沿法向在模型的剩余部分范围内移动平面</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="113"/>
        <source>Offset:</source>
        <translation>偏移：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="125"/>
        <source>Tilt:</source>
        <translation>倾斜：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="126"/>
        <source>Azimuth:</source>
        <translation>方位角：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="135"/>
        <source>Rotary angle:</source>
        <translation>旋转角度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="138"/>
        <source>&amp;Add plane</source>
        <translation>添加平面(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="141"/>
        <source>Splits the piece above the selected plane in two (or, with no plane selected, cuts what is left on the platform at mid-height)</source>
        <translation>将所选平面上方的部分一分为二（若未选择平面，则在半高处切割平台上剩余的部分）</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="143"/>
        <source>&amp;Delete plane</source>
        <translation>删除平面(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="145"/>
        <source>Updating the plan...</source>
        <translation>正在更新方案...</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="261"/>
        <source>No plan to edit: run a search or open a plan.</source>
        <translation>没有可编辑的方案：请运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="263"/>
        <source>This plan is shown without its model: open the model it was made from to edit it.</source>
        <translation>此方案显示时没有其模型：请打开生成该方案的模型后再编辑。</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="265"/>
        <source>Select a plane to move, tilt or delete it. Every change can be undone (Ctrl+Z).</source>
        <translation>选择一个平面即可移动、倾斜或删除它。每次更改都可以撤销（Ctrl+Z）。</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="278"/>
        <source>J_G before: %1 mm² (the whole model printed along up)
J_G after: %2 mm² (%3 mm² before editing)</source>
        <translation>J_G 之前：%1 mm²（整个模型沿向上方向打印）
J_G 之后：%2 mm²（编辑前为 %3 mm²）</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="425"/>
        <source>Tilting turns the plane about the middle of its cut, so its offset (measured from the origin along the normal) went from %1 mm to %2 mm.</source>
        <translation>倾斜时平面绕其切口中心旋转，因此其偏移（从原点沿法向测量）由 %1 mm 变为 %2 mm。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PoseSearchBox</name>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="31"/>
        <source>given up</source>
        <translation>给定方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="32"/>
        <source>resting</source>
        <translation>稳定放置</translation>
    </message>
    <message>
        <source>sampled</source>
        <translation type="vanished">采样</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="39"/>
        <source>Best pose</source>
        <translation>最佳姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="46"/>
        <source>Poses tried: the current up and the poses the model stands in on its own</source>
        <translation>尝试的姿态：当前向上方向以及模型能自行站立的姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="57"/>
        <source>Find best pose</source>
        <translation>查找最佳姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="59"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="140"/>
        <source>Try how the model could stand on the platform, each pose with its own decomposition, and keep the one with the least risky area left</source>
        <translation>尝试模型在平台上的各种摆放方式，每个姿态各自分解，并保留剩余风险面积最小的姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="61"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Up</source>
        <translation>向上方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Contact (mm²)</source>
        <translation>接触面积 (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Margin (mm)</source>
        <translation>余量 (mm)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="77"/>
        <source>Area of the patch of the model&apos;s convex hull that stands on the platform in this pose</source>
        <translation>在此姿态下模型凸包与平台接触部分的面积</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="79"/>
        <source>How far inside that patch the centre of mass falls: the model stands only when it is positive</source>
        <translation>重心投影位于该接触面内的距离：仅当其为正时模型才能站稳</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Risky area (mm²)</source>
        <translation>风险面积 (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="51"/>
        <source>Poses given the full search with the Search tab&apos;s settings: the current up first, then the best-scored others. The others are scored with a quick greedy plan, except those ruled out: poses no plan of which could beat the current up&apos;s</source>
        <translation>使用“搜索”选项卡设置进行完整搜索的姿态：先是当前向上方向，然后是评分最好的其他姿态。其余姿态用快速贪心方案评估，已排除的除外：其任何方案都不可能胜过当前向上方向方案的姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>J_G (mm²)</source>
        <translation>J_G (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Regions</source>
        <translation>区域</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="82"/>
        <source>Risky area of the whole model printed along this up alone (J_G before)</source>
        <translation>整个模型仅沿此向上方向打印时的风险面积（J_G 之前）</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="83"/>
        <source>J_G of the plan found for this pose</source>
        <translation>为此姿态找到的方案的 J_G</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="90"/>
        <source>Use this pose</source>
        <translation>使用此姿态</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="92"/>
        <source>Make the selected pose the model&apos;s up; the chosen pose&apos;s plan is shown, another pose is searched</source>
        <translation>将所选姿态设为模型的向上方向；选定的姿态直接显示其方案，其他姿态将重新搜索</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="94"/>
        <source>Show current up</source>
        <translation>显示当前向上方向</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="96"/>
        <source>End the preview of a pose: show the model with its up again</source>
        <translation>结束姿态预览：重新按模型的向上方向显示模型</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="99"/>
        <source>Poses to try:</source>
        <translation>尝试的姿态数：</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="100"/>
        <source>Full searches:</source>
        <translation>完整搜索数：</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="151"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="159"/>
        <source>Full search of the given up...</source>
        <translation>正在完整搜索给定方向...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="161"/>
        <source>Scoring the poses that could beat it with quick plans...</source>
        <translation>正在用快速方案评估可能胜过它的姿态...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="163"/>
        <source>Full searches of the best poses...</source>
        <translation>正在对最佳姿态进行完整搜索...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="164"/>
        <source>Choosing the best pose...</source>
        <translation>正在选择最佳姿态...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="169"/>
        <source>Cancelling the pose search...</source>
        <translation>正在取消姿态搜索...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="188"/>
        <source>full search</source>
        <translation>完整搜索</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="189"/>
        <source>quick plan</source>
        <translation>快速方案</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="190"/>
        <source>ruled out</source>
        <translation>已排除</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="191"/>
        <source>not scored</source>
        <translation>未评估</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="194"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="201"/>
        <source>-</source>
        <translation>-</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="193"/>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="213"/>
        <source>Not searched: at least %1 mm² of this pose&apos;s overhang cannot be saved by any direction the machine prints along, more than the J_G of the given up&apos;s plan, so it could not win</source>
        <translation>未搜索：此姿态至少有 %1 mm² 的悬垂在机器可打印的任何方向上都无法避免，超过给定方向方案的 J_G，因此它不可能胜出</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="218"/>
        <source>chosen</source>
        <translation>选定</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/pose_search_box.cpp" line="223"/>
        <source>Best pose: up %1 (%2), J_G %3 mm², %n region(s).</source>
        <translation>
            <numerusform>最佳姿态：向上方向 %1（%2），J_G %3 mm²，%n 个区域。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="225"/>
        <source>Cancelled: the poses that finished are listed. %1</source>
        <translation>已取消：已完成的姿态已列出。%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="252"/>
        <source>, in use</source>
        <translation>，使用中</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PoseSearchJob</name>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="83"/>
        <source>Not enough memory for the pose search: lower the beam width, the number of normals or the number of poses.</source>
        <translation>内存不足，无法进行姿态搜索：请减小束宽、法向数量或姿态数量。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="87"/>
        <location filename="../ui/jobs/pose_search_job.cpp" line="91"/>
        <source>Unexpected error during the pose search.</source>
        <translation>姿态搜索过程中发生意外错误。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="115"/>
        <source>The pose search was cancelled before any pose finished.</source>
        <translation>姿态搜索在任何姿态完成之前被取消。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrintRunDriver</name>
    <message>
        <location filename="../ui/device/print_run_driver.cpp" line="172"/>
        <source>the link to %1 was lost: the run is paused; press Resume once the link is back</source>
        <translation>与 %1 的链路已中断：运行已暂停；链路恢复后请按“继续”</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrinterLinkOwner</name>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="90"/>
        <source>The printer does not answer yet; MultiDir keeps trying. %1</source>
        <translation>打印机尚未应答；MultiDir 会继续尝试。%1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="120"/>
        <location filename="../ui/device/printer_link_owner.cpp" line="166"/>
        <source>Printer E-STOP</source>
        <translation>打印机急停</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="122"/>
        <source>%1 refused: no printer is connected.</source>
        <translation>%1 被拒绝：未连接打印机。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="139"/>
        <source>Restart firmware</source>
        <translation>重启固件</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="139"/>
        <source>Restart firmware refused: no printer is connected.</source>
        <translation>“重启固件”被拒绝：未连接打印机。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrinterSection</name>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="45"/>
        <source>%1 °C (off)</source>
        <translation>%1 °C（关闭）</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="46"/>
        <source>%1 / %2 °C</source>
        <translation>%1 / %2 °C</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="53"/>
        <location filename="../ui/device/printer_section.cpp" line="294"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="55"/>
        <source>standby (no job)</source>
        <translation>待机（无作业）</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="57"/>
        <source>printing</source>
        <translation>正在打印</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="59"/>
        <source>paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="61"/>
        <source>complete</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="63"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="65"/>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="75"/>
        <source>Printer</source>
        <translation>打印机</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="79"/>
        <source>http://192.168.0.20:7125</source>
        <translation>http://192.168.0.20:7125</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="80"/>
        <source>The printer&apos;s address: Moonraker (Klipper) as http://HOST:PORT or HOST:PORT (port 7125).</source>
        <translation>打印机地址：Moonraker（Klipper），格式为 http://HOST:PORT 或 HOST:PORT（端口 7125）。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="84"/>
        <location filename="../ui/device/printer_section.cpp" line="298"/>
        <location filename="../ui/device/printer_section.cpp" line="312"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="85"/>
        <source>Only when the printer asks for one (Moonraker&apos;s [authorization]). Not remembered.</source>
        <translation>仅在打印机要求时填写（Moonraker 的 [authorization]）。不会被保存。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="86"/>
        <source>Connect printer</source>
        <translation>连接打印机</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="87"/>
        <source>Connects to the printer; a print run then sends each region&apos;s G-code to it.</source>
        <translation>连接打印机；之后打印运行会将每个区域的 G 代码发送给它。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="88"/>
        <source>Disconnect printer</source>
        <translation>断开打印机</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="89"/>
        <source>Closes the link without commanding the printer: a job on it goes on.</source>
        <translation>关闭链路而不向打印机发送命令：打印机上的作业会继续进行。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="90"/>
        <source>Clear printer E-STOP</source>
        <translation>清除打印机急停</translation>
    </message>
    <message>
        <source>Allows jobs again once the printer confirmed the emergency stop. A Klipper printer also needs FIRMWARE_RESTART on its console.</source>
        <translation type="vanished">打印机确认急停后，重新允许作业。Klipper 打印机还需在其控制台上执行 FIRMWARE_RESTART。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="112"/>
        <source>Address:</source>
        <translation>地址：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="113"/>
        <source>API key:</source>
        <translation>API 密钥：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="118"/>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="119"/>
        <source>Job:</source>
        <translation>作业：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="120"/>
        <source>Firmware:</source>
        <translation>固件：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="121"/>
        <source>Printer says:</source>
        <translation>打印机消息：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="122"/>
        <source>Extruder:</source>
        <translation>挤出机：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="123"/>
        <source>Bed:</source>
        <translation>热床：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="124"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="125"/>
        <source>Progress:</source>
        <translation>进度：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="126"/>
        <source>Job time left:</source>
        <translation>作业剩余时间：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="127"/>
        <source>Last problem:</source>
        <translation>最近的问题：</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="154"/>
        <source>Connected to %1.</source>
        <translation>已连接到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="172"/>
        <source>The link to %1 was lost at %2: its values are not the printer&apos;s any more, and it may still be printing. MultiDir keeps trying.</source>
        <translation>与 %1 的链路于 %2 中断：这些数值已不再反映打印机的状态，且它可能仍在打印。MultiDir 会继续尝试。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="188"/>
        <source>Cannot connect to the printer: %1</source>
        <translation>无法连接打印机：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="192"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="197"/>
        <source>Printer disconnected.</source>
        <translation>打印机已断开。</translation>
    </message>
    <message>
        <source>Printer E-STOP cleared. A Klipper printer needs FIRMWARE_RESTART before its next job.</source>
        <translation type="vanished">打印机急停已清除。Klipper 打印机在下一个作业前需要执行 FIRMWARE_RESTART。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="210"/>
        <source>Clear printer E-STOP refused: %1</source>
        <translation>清除打印机急停被拒绝：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="251"/>
        <source>step %1 of %2: %3</source>
        <translation>步骤 %1 / %2：%3</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="254"/>
        <source>not started</source>
        <translation>未开始</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="257"/>
        <source>%1 of %2 (not a step of this run)</source>
        <translation>%2 已完成 %1（不属于本次运行的步骤）</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="263"/>
        <source>none: every step is printed</source>
        <translation>无：所有步骤均已打印</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="266"/>
        <source>no estimate: slice the plan before starting the run</source>
        <translation>无估算：请在开始运行前对方案切片</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="268"/>
        <source>%1 of printing (done about %2; platform moves not counted)</source>
        <translation>打印用时 %1（约 %2 完成；不含平台移动）</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="279"/>
        <source>Disconnected</source>
        <translation>已断开</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="281"/>
        <source>Not reachable; MultiDir keeps trying…</source>
        <translation>无法访问；MultiDir 会继续尝试…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="283"/>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="285"/>
        <source>Link lost at %1; MultiDir keeps trying…</source>
        <translation>链路于 %1 中断；MultiDir 会继续尝试…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="287"/>
        <source>Connected to %1</source>
        <translation>已连接到 %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="295"/>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="340"/>
        <source>%1 does not answer: %2</source>
        <translation>%1 没有应答：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="342"/>
        <source>The printer&apos;s firmware is %1: %2</source>
        <translation>打印机固件处于 %1 状态：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="344"/>
        <source>it says nothing more</source>
        <translation>无更多信息</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="346"/>
        <source>The print run is paused: %1.</source>
        <translation>打印运行已暂停：%1。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="91"/>
        <source>Allows jobs again once the printer confirmed the emergency stop. A printer whose firmware the stop shut down also needs Restart firmware.</source>
        <translation>打印机确认急停后，再次允许任务。急停使其固件关闭的打印机还需要“重启固件”。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="94"/>
        <source>Restart firmware</source>
        <translation>重启固件</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="95"/>
        <source>After an emergency stop: Klipper&apos;s FIRMWARE_RESTART (through Moonraker), or OctoPrint connecting to the printer again (which resets its board). Asks first.</source>
        <translation>急停之后：Klipper 的 FIRMWARE_RESTART（通过 Moonraker），或 OctoPrint 重新连接打印机（这会重置其主板）。会先询问。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="203"/>
        <source>Printer E-STOP cleared.</source>
        <translation>打印机急停已清除。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="205"/>
        <source>Printer E-STOP cleared. Its firmware is %1: it needs Restart firmware (Klipper&apos;s FIRMWARE_RESTART) before its next job.</source>
        <translation>打印机急停已清除。其固件状态为 %1：在下一个任务之前需要“重启固件”（Klipper 的 FIRMWARE_RESTART）。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="145"/>
        <source>%1 is restarting its firmware; the Firmware line shows &quot;ready&quot; once it is back.</source>
        <translation>%1 正在重启其固件；恢复后“固件”一行将显示“ready”。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="149"/>
        <source>Restart firmware refused: %1</source>
        <translation>“重启固件”被拒绝：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="214"/>
        <source>Restart Printer Firmware</source>
        <translation>重启打印机固件</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="215"/>
        <source>Restart the firmware of %1?</source>
        <translation>重启 %1 的固件？</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="218"/>
        <source>The firmware takes the heaters and motors back: make sure whatever caused the emergency stop is fixed and nothing is in the printer&apos;s way.</source>
        <translation>固件将重新接管加热器和电机：请确保导致急停的原因已排除，并且没有任何东西挡住打印机。</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="220"/>
        <source>&amp;Restart Firmware</source>
        <translation>重启固件(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="228"/>
        <source>Restarting the firmware of %1…</source>
        <translation>正在重启 %1 的固件…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="308"/>
        <source>unknown since %1: the printer&apos;s link is lost</source>
        <translation>自 %1 起未知：与打印机的链路已中断</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="325"/>
        <source>%1&apos;s firmware is ready again.</source>
        <translation>%1 的固件已再次就绪。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ProjectSession</name>
    <message>
        <location filename="../ui/project/project_session.cpp" line="87"/>
        <source>Open &amp;Project...</source>
        <translation>打开项目(&amp;P)...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="89"/>
        <source>Open a MultiDir project (.multidir): its model, settings and plan</source>
        <translation>打开 MultiDir 项目（.multidir）：包括其模型、设置和方案</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="93"/>
        <source>&amp;Save Project</source>
        <translation>保存项目(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="96"/>
        <source>Save the model reference, the settings and the plan in a project file</source>
        <translation>将模型引用、设置和方案保存到项目文件中</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="97"/>
        <source>Save Project &amp;As...</source>
        <translation>项目另存为(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="108"/>
        <source>There is no model to save a project for: open a model first.</source>
        <translation>没有可为之保存项目的模型：请先打开一个模型。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="117"/>
        <source>The model shown has no file (it is the regions of a plan opened without its model): open the model itself to save a project.</source>
        <translation>当前显示的模型没有对应的文件（它是一个在没有模型的情况下打开的方案的各个区域）：请打开模型本身以保存项目。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="137"/>
        <source>Wait until the project has opened before saving.</source>
        <translation>请等项目打开完成后再保存。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="140"/>
        <source>Cannot save the project: %1</source>
        <translation>无法保存项目：%1</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="143"/>
        <source>Could not save the project %1: %2 (%3)</source>
        <translation>无法保存项目 %1：%2（%3）</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="150"/>
        <source>Project saved to %1.</source>
        <translation>项目已保存到 %1。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="162"/>
        <location filename="../ui/project/project_session.cpp" line="176"/>
        <location filename="../ui/project/project_session.cpp" line="181"/>
        <source>Save Project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="176"/>
        <source>MultiDir projects (*.multidir)</source>
        <translation>MultiDir 项目 (*.multidir)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="186"/>
        <location filename="../ui/project/project_session.cpp" line="579"/>
        <source>Open Project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="187"/>
        <source>MultiDir projects (*.multidir);;All files (*)</source>
        <translation>MultiDir 项目 (*.multidir);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="221"/>
        <source>Search Running</source>
        <translation>搜索正在运行</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="222"/>
        <source>A search is running on %1.</source>
        <translation>正在对 %1 运行搜索。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="223"/>
        <source>the model shown</source>
        <translation>当前显示的模型</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="226"/>
        <source>Stop it? Its result is then dropped.</source>
        <translation>是否停止？其结果将被丢弃。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="227"/>
        <source>S&amp;top the Search</source>
        <translation>停止搜索(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="251"/>
        <source>%1 is no longer there; it was taken off the recent files.</source>
        <translation>%1 已不存在，已将其从最近打开的文件中移除。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="271"/>
        <source>Cannot open %1: drop a mesh file (.stl, .obj, .off, .ply) or a MultiDir project (.multidir).</source>
        <translation>无法打开 %1：请拖放网格文件（.stl、.obj、.off、.ply）或 MultiDir 项目（.multidir）。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="284"/>
        <source>There is no autosaved project to recover.</source>
        <translation>没有可恢复的自动保存项目。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="294"/>
        <source>Recover Unsaved Work</source>
        <translation>恢复未保存的工作</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="295"/>
        <source>MultiDir Studio did not close properly. Recover the project it autosaved on %1?</source>
        <translation>MultiDir Studio 未正常关闭。是否恢复它在 %1 自动保存的项目？</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="300"/>
        <source>It was an untitled project.</source>
        <translation>这是一个未命名的项目。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="301"/>
        <source>It holds unsaved changes to %1.</source>
        <translation>其中包含对 %1 的未保存更改。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="302"/>
        <source>&amp;Recover</source>
        <translation>恢复(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="303"/>
        <source>&amp;Discard</source>
        <translation>丢弃(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="304"/>
        <source>&amp;Later</source>
        <translation>稍后(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="348"/>
        <source>untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="349"/>
        <source>Unsaved Changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="350"/>
        <source>The project %1 has changes that are not saved.</source>
        <translation>项目 %1 有尚未保存的更改。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="353"/>
        <source>Save them first?</source>
        <translation>是否先保存？</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="450"/>
        <location filename="../ui/project/project_session.cpp" line="488"/>
        <source>Opening %1 was interrupted: another model was opened.</source>
        <translation>打开 %1 时被中断：另一个模型已被打开。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="468"/>
        <source>Rebuilding the plan of %1...</source>
        <translation>正在重建 %1 的方案...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="495"/>
        <source>The model file %1 changed since the project was saved; the plan was recomputed on the changed file.</source>
        <translation>模型文件 %1 在项目保存后已发生变化；方案已根据变化后的文件重新计算。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="509"/>
        <source>The rebuilt plan leaves %1 mm² of risky area; the project saved %2 mm².</source>
        <translation>重建的方案剩余 %1 mm² 风险面积；项目中保存的是 %2 mm²。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="514"/>
        <source>The plan could not be rebuilt on this model (%1); the model is shown without it.</source>
        <translation>无法在此模型上重建方案（%1）；模型将不带方案显示。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="530"/>
        <source>Recovered the autosaved project.</source>
        <translation>已恢复自动保存的项目。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="531"/>
        <source>Project %1 opened.</source>
        <translation>已打开项目 %1。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="534"/>
        <source>Project %1</source>
        <translation>项目 %1</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="544"/>
        <source>Could not open the project %1: %2</source>
        <translation>无法打开项目 %1：%2</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="559"/>
        <source>Could not open the project %1: its model %2 is missing.</source>
        <translation>无法打开项目 %1：缺少其模型 %2。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="560"/>
        <source>Put the model back at %1, or open the model where it is now and save the project again.</source>
        <translation>请将模型放回 %1，或从模型现在所在的位置打开它，然后重新保存项目。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="565"/>
        <source>Opening the project %1...</source>
        <translation>正在打开项目 %1...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="578"/>
        <source>%1 is still open.</source>
        <translation>%1 仍处于打开状态。</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="608"/>
        <source>MultiDir Studio[*]</source>
        <translation>MultiDir Studio[*]</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="608"/>
        <source>%1[*] - MultiDir Studio</source>
        <translation>%1[*] - MultiDir Studio</translation>
    </message>
</context>
<context>
    <name>multidir::ui::RecentFilesMenu</name>
    <message>
        <location filename="../ui/project/recent_files.cpp" line="41"/>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/project/recent_files.cpp" line="68"/>
        <source>&amp;Clear Recent</source>
        <translation>清除最近记录(&amp;C)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::RobotCellSection</name>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="63"/>
        <source>Robot cell (Universal Robots)</source>
        <translation>机器人单元（Universal Robots）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="70"/>
        <source>host or host:port (the dashboard&apos;s port; UR&apos;s own 29999 when left out)</source>
        <translation>主机或 主机:端口（仪表板端口；省略时为 UR 默认的 29999）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="73"/>
        <source>the folder &apos;multidir robot-program&apos; wrote</source>
        <translation>“multidir robot-program”写出的文件夹</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="74"/>
        <source>Open job folder…</source>
        <translation>打开作业文件夹…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="75"/>
        <source>Convert the sliced job</source>
        <translation>转换已切片的作业</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="77"/>
        <source>The plan&apos;s sliced job turned into the cell&apos;s programs (as multidir robot-program does), for the cell on the Machine tab</source>
        <translation>将计划的切片作业转换为单元的程序（与 multidir robot-program 相同），用于“机器”选项卡中的单元</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="79"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="84"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="85"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="91"/>
        <source>Start job</source>
        <translation>开始作业</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="92"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="93"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="94"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="95"/>
        <location filename="../ui/device/robot_cell_section.cpp" line="503"/>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="115"/>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="117"/>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="118"/>
        <source>Joints:</source>
        <translation>关节：</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="119"/>
        <source>Robot job:</source>
        <translation>机器人作业：</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="121"/>
        <source>Step:</source>
        <translation>步骤：</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="134"/>
        <source>Conversion cancelled.</source>
        <translation>转换已取消。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="148"/>
        <source>%1 of %2: %3 sent</source>
        <translation>第 %1 步，共 %2 步：已发送 %3</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="153"/>
        <source>movel %1 of %2</source>
        <translation>movel %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="153"/>
        <source>between movels (a joint move)</source>
        <translation>在 movel 之间（关节运动）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="154"/>
        <source>%1 of %2: %3, %4 %, about %5 left</source>
        <translation>第 %1 步，共 %2 步：%3，%4 %，剩余约 %5</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="162"/>
        <source>The robot reports: %1</source>
        <translation>机器人报告：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="165"/>
        <source>Cannot pause: %1. Stop ends the run.</source>
        <translation>无法暂停：%1。停止将结束运行。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="167"/>
        <source>paused after movel %1 of %2; the extruder stopped, the platform %3 mm off the nozzle</source>
        <translation>在 movel %1 / %2 之后暂停；挤出机已停止，平台离开喷嘴 %3 mm</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="172"/>
        <source>%1 of %2: %3</source>
        <translation>第 %1 步，共 %2 步：%3</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="173"/>
        <source>Paused at a safe point. Resume goes on from there; Stop ends the run.</source>
        <translation>已在安全点暂停。继续将从该处接着运行；停止将结束运行。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="178"/>
        <source>Resuming step %1 after movel %2: back down to the nozzle, then the rest of the step.</source>
        <translation>在 movel %2 之后继续第 %1 步：先回到喷嘴处，然后运行该步骤的其余部分。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="186"/>
        <source>%1 of %2 done in %3 of the robot&apos;s time</source>
        <translation>第 %1 步（共 %2 步）已完成，用时 %3（机器人时间）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="217"/>
        <source>The link to the robot at %1 is lost (%2). The robot&apos;s values are unknown; MultiDir keeps trying to reconnect and sends a latched stop first thing once it is back.</source>
        <translation>与 %1 处机器人的连接已断开（%2）。机器人的数值未知；MultiDir 会持续尝试重新连接，连接恢复后首先发送保持中的停止命令。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="220"/>
        <source>The robot job run is ending: it stops the program.</source>
        <translation>机器人作业运行正在结束：它会停止程序。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="226"/>
        <source>Open a robot job folder (multidir robot-program OUT)</source>
        <translation>打开机器人作业文件夹（multidir robot-program OUT）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="233"/>
        <source>There is no robot cell: choose the machine &quot;robot arm under a fixed extruder&quot;.</source>
        <translation>没有机器人单元：请选择机器“固定挤出机下的机械臂”。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="238"/>
        <source>The plan shown is not sliced: slice it with the cell&apos;s profile (ur5-cell-0.8) first.</source>
        <translation>显示的计划尚未切片：请先用单元的配置（ur5-cell-0.8）切片。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="243"/>
        <source>No folder for the converted job: %1</source>
        <translation>没有用于转换后作业的文件夹：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="275"/>
        <source>The sliced job cannot be converted for the cell: %1</source>
        <translation>无法为该单元转换切片作业：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="280"/>
        <source>Converted for the cell: %1 steps in %2.</source>
        <translation>已为该单元转换：%1 个步骤，位于 %2。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="288"/>
        <source>Converting the sliced job for the cell…</source>
        <translation>正在为该单元转换切片作业…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="299"/>
        <source>The robot&apos;s address: %1</source>
        <translation>机器人地址：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="309"/>
        <source>Connecting to the robot at %1…</source>
        <translation>正在连接 %1 处的机器人…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="327"/>
        <source>The robot at %1 cannot be reached: %2</source>
        <translation>无法连接 %1 处的机器人：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="331"/>
        <source>Connected to the robot at %1.</source>
        <translation>已连接到 %1 处的机器人。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="340"/>
        <source>A robot job run is under way: Stop it before disconnecting.</source>
        <translation>机器人作业正在运行：断开前请先停止它。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="354"/>
        <source>Start refused: %1</source>
        <translation>拒绝开始：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="358"/>
        <source>no robot is connected: Connect first.</source>
        <translation>未连接机器人：请先连接。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="366"/>
        <source>the document has no robot cell: set the cell on the Machine tab (the job was made for %1).</source>
        <translation>文档中没有机器人单元：请在“机器”选项卡中设置单元（该作业是为 %1 生成的）。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="371"/>
        <source>the job&apos;s cell (%1) cannot be read: %2</source>
        <translation>无法读取作业的单元（%1）：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="374"/>
        <source>the job&apos;s cell (%1) is not the cell on the Machine tab: convert the job again with this cell, or load the job&apos;s cell on the Machine tab.</source>
        <translation>作业的单元（%1）不是“机器”选项卡中的单元：请用此单元重新转换作业，或在“机器”选项卡中加载作业的单元。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="379"/>
        <source>no plan is shown: open the plan the job was made from.</source>
        <translation>未显示计划：请打开生成该作业的计划。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="382"/>
        <source>the job was converted from another plan than the one shown: convert the sliced job again.</source>
        <translation>该作业是从另一个计划转换的，而非当前显示的计划：请重新转换切片作业。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="384"/>
        <source>the job has %1 steps but the plan shown has %2 regions: it was made from another plan.</source>
        <translation>作业有 %1 个步骤，而显示的计划有 %2 个区域：它是由另一个计划生成的。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="391"/>
        <source>the robot has not confirmed its stop yet (%1).</source>
        <translation>机器人尚未确认其停止（%1）。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="409"/>
        <source>starting: %1 steps</source>
        <translation>正在开始：%1 个步骤</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="410"/>
        <source>Robot job started: %1 steps.</source>
        <translation>机器人作业已开始：%1 个步骤。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="418"/>
        <source>Pause asked for: the arm finishes the move under way, the extruder stops and the platform backs off the nozzle.</source>
        <translation>已请求暂停：机械臂完成当前运动，挤出机停止，平台离开喷嘴。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="448"/>
        <source>E-STOP sent to the robot (stop, then power off). To go on: release it on the teach pendant if pressed there; Start powers the arm on again once the robot confirmed the stop.</source>
        <translation>已向机器人发送急停（停止，然后断电）。继续：如在示教器上按下了急停，请将其释放；机器人确认停止后，“开始”会重新为机械臂上电。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="460"/>
        <source>done: %1 steps printed</source>
        <translation>完成：已打印 %1 个步骤</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="461"/>
        <source>The robot job is done: %1 steps printed.</source>
        <translation>机器人作业已完成：已打印 %1 个步骤。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="465"/>
        <source>The robot did not start the job: %1</source>
        <translation>机器人未开始该作业：%1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="469"/>
        <source>stopped in step %1 of %2</source>
        <translation>在第 %1 步（共 %2 步）停止</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="470"/>
        <source>The run stopped in step %1: %2</source>
        <translation>运行在第 %1 步停止：%2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="487"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="488"/>
        <location filename="../ui/device/robot_cell_section.cpp" line="493"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="492"/>
        <source>unknown: the link is lost (%1)</source>
        <translation>未知：连接已断开（%1）</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="495"/>
        <source>robot mode %1, safety mode %2, program %3</source>
        <translation>机器人模式 %1，安全模式 %2，程序 %3</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="500"/>
        <source>%1 deg</source>
        <translation>%1 度</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="503"/>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="504"/>
        <source>Robot: %1 confirmed by the robot.</source>
        <translation>机器人：%1 已由机器人确认。</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="505"/>
        <source>Robot: %1 not confirmed yet (%2); MultiDir keeps resending it.</source>
        <translation>机器人：%1 尚未确认（%2）；MultiDir 会继续重发。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchJob</name>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="26"/>
        <source>The search was cancelled while growing supports: the plan is shown without them.</source>
        <translation>搜索在生成支撑时被取消：方案将不带支撑显示。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="28"/>
        <source>The supports could not be grown: %1 (%2)</source>
        <translation>无法生成支撑：%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="32"/>
        <source>Not enough memory to grow the supports: the plan is shown without them.</source>
        <translation>内存不足，无法生成支撑：方案将不带支撑显示。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="34"/>
        <source>Unexpected error while growing the supports: %1</source>
        <translation>生成支撑时发生意外错误：%1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="36"/>
        <source>Unexpected error while growing the supports.</source>
        <translation>生成支撑时发生意外错误。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="96"/>
        <source>growing supports</source>
        <translation>正在生成支撑</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="107"/>
        <source>Not enough memory for this search: lower the beam width or the number of normals.</source>
        <translation>内存不足，无法进行此搜索：请减小束宽或法向数量。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="110"/>
        <location filename="../ui/jobs/search_job.cpp" line="114"/>
        <source>Unexpected error during the search.</source>
        <translation>搜索过程中发生意外错误。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchPanel</name>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="46"/>
        <source>Beam search (Algorithm 1)</source>
        <translation>束搜索（算法 1）</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="47"/>
        <source>Constrained greedy</source>
        <translation>受约束贪心</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="48"/>
        <source>Greedy</source>
        <translation>贪心</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="53"/>
        <source>How many partial plans each level keeps (b)</source>
        <translation>每一层保留的部分方案数量 (b)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="59"/>
        <source>w: every region cut off keeps at least the model&apos;s volume divided by w</source>
        <translation>w：每个切下的区域至少保留模型体积除以 w</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="64"/>
        <source>Beam search only: runs at this many region scales side by side, the smallest region V/w, V/2w, V/4w, ..., the beam width shared among them, and keeps the best plan. No single w suits every model. 1: one beam search at w</source>
        <translation>仅限束搜索：在这么多个区域尺度上并行运行（最小区域为 V/w、V/2w、V/4w……），束宽在它们之间分配，保留最佳方案。没有一个 w 适合所有模型。1：在 w 上进行一次束搜索</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="71"/>
        <source>Candidate normals sampled on the whole sphere (5-DOF)</source>
        <translation>在整个球面上采样的候选法向（5 自由度）</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="76"/>
        <location filename="../ui/panels/search_panel.cpp" line="90"/>
        <source> mm</source>
        <translation> 毫米</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="78"/>
        <source>Distance between candidate planes along each normal</source>
        <translation>沿每个法向的候选平面间距</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="83"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="85"/>
        <source>Maximal self-supporting angle the search plans for</source>
        <translation>搜索所依据的最大自支撑角度</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="92"/>
        <source>No region, the one on the platform included, is thinner than this along its printing direction</source>
        <translation>任何区域（包括平台上的区域）沿其打印方向的厚度都不小于此值</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="98"/>
        <source> % of J_G</source>
        <translation> % 的 J_G</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="100"/>
        <source>A plane stays only if removing it would raise J_G by at least this share of J_G before (and by at least 1 mm²): each region costs a platform move and a seam</source>
        <translation>仅当移除某个平面会使 J_G 至少增加移除前 J_G 的这一比例（且至少 1 mm²）时，才保留该平面：每个区域都需要一次平台移动并产生一条接缝</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="123"/>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="124"/>
        <source>After the search, move every plane continuously (normal and offset) to lower J_G further, every constraint kept; higher values refine more finely and take longer</source>
        <translation>搜索之后,在满足所有约束的前提下连续移动每个平面(法向与偏移)以进一步降低 J_G;数值越高细化越精、耗时越长</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="140"/>
        <source>machine&apos;s axis only</source>
        <translation>仅机器自身的轴</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="141"/>
        <source>4-DOF: also try this many rotation axes spread over 180° and keep the best</source>
        <translation>4 自由度：另外尝试这么多分布在 180° 内的旋转轴，并保留最佳的</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="144"/>
        <source>Scheme:</source>
        <translation>方案类型：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="145"/>
        <source>Beam width:</source>
        <translation>束宽：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="147"/>
        <source>Volume divisor w:</source>
        <translation>体积除数 w：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="148"/>
        <source>Scales:</source>
        <translation>尺度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="150"/>
        <source>Normals:</source>
        <translation>法向数：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="151"/>
        <source>Offset step:</source>
        <translation>偏移步长：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="152"/>
        <source>Max. overhang angle α:</source>
        <translation>最大悬垂角 α：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="153"/>
        <source>Min. region height:</source>
        <translation>最小区域高度：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="154"/>
        <source>Min. gain per plane:</source>
        <translation>每个平面的最小增益：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="159"/>
        <source>Polish the planes:</source>
        <translation>平面精修:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="126"/>
        <source>also the finalists</source>
        <translation>也打磨候选方案</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="129"/>
        <source>Also polish the search&apos;s best plan for every other number of cuts that may beat its own plan, and keep the least J_G: the plan changes less with the settings</source>
        <translation>也打磨搜索在其他每个切割数下可能胜过其自身方案的最佳方案，并保留 J_G 最小者：方案随设置的变化更小</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="131"/>
        <source>the tails of the polished plan</source>
        <translation>打磨后方案的后续平面</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="134"/>
        <source>After polishing, search the plan&apos;s later planes again from each of its polished states and keep a lower plan found there: lower J_G on some models, about twice the time</source>
        <translation>打磨后，从方案的每个打磨状态重新搜索其后续平面，并保留在那里找到的更低方案：某些模型的 J_G 更低，耗时约为两倍</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="160"/>
        <source>Search again:</source>
        <translation>重新搜索：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="161"/>
        <source>Axes to try:</source>
        <translation>尝试的轴数：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="168"/>
        <source>&amp;Run search</source>
        <translation>运行搜索(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="171"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="202"/>
        <source>Progress</source>
        <translation>进度</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="210"/>
        <source>Level:</source>
        <translation>层级：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="211"/>
        <source>Beams alive:</source>
        <translation>存活束：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="212"/>
        <source>Best J_G:</source>
        <translation>最佳 J_G：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="213"/>
        <source>Candidates scored:</source>
        <translation>已评估候选：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="235"/>
        <source>Open a model first.</source>
        <translation>请先打开一个模型。</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="301"/>
        <source>Search for clipping planes that make the model printable with less support</source>
        <translation>搜索能让模型以更少支撑打印的切割平面</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="367"/>
        <source>%1 (polishing)</source>
        <translation>%1(精修中)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="382"/>
        <source>Cancelling: keeping the best plan so far... %1</source>
        <translation>正在取消：保留目前的最佳方案... %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="384"/>
        <source>%1 %2 - %3</source>
        <translation>%1 %2 - %3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="386"/>
        <source>Level 1 of %1: scoring candidates... %2</source>
        <translation>层级 1 / %1：正在评估候选... %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="387"/>
        <source>Scoring candidates... %1</source>
        <translation>正在评估候选... %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="391"/>
        <source>Polishing the planes: %1 % · best J_G %2 mm² · %3</source>
        <translation>平面精修:%1 % · 最佳 J_G %2 mm² · %3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="396"/>
        <source>Level %1 of %2</source>
        <translation>层级 %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="396"/>
        <source>Level %1</source>
        <translation>层级 %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="397"/>
        <source>Axis %1 of %2, %3</source>
        <translation>第 %1 / %2 个轴，%3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="400"/>
        <source>%1 · beams alive: %2 · best J_G %3 mm² · %4 candidates · %5</source>
        <translation>%1 · 存活束：%2 · 最佳 J_G %3 mm² · %4 个候选 · %5</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="439"/>
        <source>The search ran on a simplified copy of %1 faces; its planes then cut the full model, and every number shown is the full model&apos;s.</source>
        <translation>搜索在有 %1 个面的简化副本上进行；随后用其平面切割完整模型，显示的所有数值均针对完整模型。</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="462"/>
        <source>Stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="340"/>
        <location filename="../ui/panels/search_panel.cpp" line="369"/>
        <location filename="../ui/panels/search_panel.cpp" line="418"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="365"/>
        <source>%1 (axis %2 of %3)</source>
        <translation>%1（第 %2 / %3 个轴）</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="417"/>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="417"/>
        <source>Done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="423"/>
        <source>Cancelled: showing the best plan found so far.</source>
        <translation>已取消：显示目前找到的最佳方案。</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="427"/>
        <source>Nothing improved: no clipping plane lowers the risky area (J_G stays %1 mm²). Try more normals, a smaller offset step, a larger w or another machine.</source>
        <translation>没有改进：没有切割平面能减少风险面积（J_G 仍为 %1 mm²）。请尝试更多法向、更小的偏移步长、更大的 w 或其他机器。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="432"/>
        <source>Not support-free: %1 mm² still needs support (was %2 mm²), in %n region(s).</source>
        <translation>
            <numerusform>并非无支撑：仍有 %1 mm² 需要支撑（原为 %2 mm²），共 %n 个区域。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="436"/>
        <source>Support-free in %n region(s) (J_G was %1 mm²).</source>
        <translation>
            <numerusform>分为 %n 个区域后无需支撑（J_G 原为 %1 mm²）。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="454"/>
        <source>Failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="455"/>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="106"/>
        <source> mm²</source>
        <translation> mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="108"/>
        <source>Apart: the risky area one more part must save, for its dowels and handling (the support whose print time equals its dowels&apos;)</source>
        <translation>分开打印：每多一个零件必须节省的风险面积，用于其定位销和操作（打印时间与其定位销相同的支撑）</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="114"/>
        <source> mm² per mm² of cut face</source>
        <translation> mm²/每 mm² 切割面</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="116"/>
        <source>Apart: the risky area one more part must save for every mm² of its cut face, whose two sides are printed solid</source>
        <translation>分开打印：每多一个零件，其切割面每 mm² 必须节省的风险面积（切割面两侧均为实心打印）</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="163"/>
        <source>Price of a part:</source>
        <translation>零件的代价：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="165"/>
        <source>... and of its cut face:</source>
        <translation>……及其切割面的代价：</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="399"/>
        <source>Apart search (1 of 2), %1</source>
        <translation>分开打印搜索（1 / 2），%1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="399"/>
        <source>5-DOF search for the bound (2 of 2), %1</source>
        <translation>用于上界的 5-DOF 搜索（2 / 2），%1</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceDialog</name>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="82"/>
        <source>The firmware turns the platform (axis %1): one program, job.gcode, with every step.</source>
        <translation>由固件转动平台（轴 %1）：一个包含所有步骤的程序 job.gcode。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="85"/>
        <source>MultiDir turns the platform over Modbus (Hardware dock): one program per step.</source>
        <translation>由 MultiDir 通过 Modbus 转动平台（“硬件”停靠窗口）：每个步骤一个程序。</translation>
    </message>
    <message>
        <source>The firmware tilts (axis %1) and rotates (axis %2) the platform; MultiDir does not write their program yet, so it prints one-step plans only.</source>
        <translation type="vanished">由固件倾斜（轴 %1）并旋转（轴 %2）平台；MultiDir 尚不能编写其程序，因此只打印单步计划。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="27"/>
        <source>Klipper with tilt and rotation steppers, 0.4 mm nozzle</source>
        <translation>带倾斜与旋转步进电机的 Klipper,0.4 mm 喷嘴</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="28"/>
        <source>Klipper with a rotary A axis, 0.4 mm nozzle</source>
        <translation>带 A 旋转轴的 Klipper,0.4 mm 喷嘴</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="29"/>
        <source>Generic Marlin 220x220, 0.4 mm nozzle (platform over Modbus)</source>
        <translation>通用 Marlin 220x220,0.4 mm 喷嘴(平台经 Modbus)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="30"/>
        <source>Open5x-like Prusa i3, RepRapFirmware U tilt + V rotation, 0.4 mm nozzle</source>
        <translation>类 Open5x 的 Prusa i3,RepRapFirmware U 倾斜 + V 旋转,0.4 mm 喷嘴</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="32"/>
        <source>Robot arm tilting the platform, printer head moving, 0.8 mm nozzle</source>
        <translation>机械臂倾转平台,打印头移动,0.8 mm 喷嘴</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="33"/>
        <source>UR5 robot cell, fixed 0.8 mm extruder</source>
        <translation>UR5 机器人单元,固定 0.8 mm 挤出机</translation>
    </message>
    <message>
        <source>A plan printed apart is sliced part by part on plates: use &apos;multidir apart&apos; (docs/apart.md).</source>
        <translation type="vanished">分开打印的方案需逐个零件在打印板上切片:请使用 “multidir apart”(docs/apart.md)。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="65"/>
        <source>This printer cannot turn the part: it prints one-step (3-DOF) plans only.</source>
        <translation>此打印机无法转动零件:只能打印单步(3-DOF)方案。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="69"/>
        <source>This printer turns the platform about one axis: it cannot print a 5-DOF plan. Choose a printer with two firmware axes or a robot arm.</source>
        <translation>此打印机只能绕一个轴转动平台:无法打印 5-DOF 方案。请选择具有两个固件轴的打印机或机械臂。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="87"/>
        <source>The firmware tilts (axis %1) and rotates (axis %2) the platform: one program, job.gcode, with every step and the turns between them.</source>
        <translation>固件倾斜(轴 %1)并旋转(轴 %2)平台:一个程序 job.gcode,包含所有步骤及其间的转动。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="93"/>
        <source>An ordinary printer: it cannot turn the part, so it prints one-step plans only.</source>
        <translation>普通打印机：无法转动零件，因此只能打印单步骤方案。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="100"/>
        <source>Slice the Plan</source>
        <translation>对方案切片</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="115"/>
        <source>Load a PrusaSlicer .ini...</source>
        <translation>加载 PrusaSlicer .ini...</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="125"/>
        <source>How the firmware turns the platform: Klipper&apos;s MANUAL_STEPPER, or G1 A on Marlin and RepRapFirmware</source>
        <translation>固件转动平台的方式：Klipper 的 MANUAL_STEPPER，或 Marlin 和 RepRapFirmware 的 G1 A</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="130"/>
        <source>layer_height=0.3 fill_density=10%</source>
        <translation>layer_height=0.3 fill_density=10%</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="131"/>
        <source>PrusaSlicer settings over the profile&apos;s, KEY=VALUE separated by spaces</source>
        <translation>覆盖打印机配置的 PrusaSlicer 设置，格式为 KEY=VALUE，以空格分隔</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="132"/>
        <source>Also slice the whole model along up with the slicer&apos;s supports (comparison)</source>
        <translation>同时沿向上方向用切片软件的支撑对整个模型切片（用于比较）</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="136"/>
        <source>The prusa-slicer program: a name found on PATH, or a full path</source>
        <translation>prusa-slicer 程序：可在 PATH 中找到的名称，或完整路径</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="144"/>
        <source>Printer:</source>
        <translation>打印机：</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="146"/>
        <source>Dialect:</source>
        <translation>固件方言：</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="147"/>
        <source>Slicer settings:</source>
        <translation>切片设置：</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="149"/>
        <source>Slicer program:</source>
        <translation>切片程序：</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="151"/>
        <source>Slice</source>
        <translation>切片</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="182"/>
        <source>Cannot use the printer profile: %1</source>
        <translation>无法使用打印机配置：%1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="187"/>
        <source>%1: %2</source>
        <translation>%1:%2</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="223"/>
        <source>Load a PrusaSlicer Printer Profile</source>
        <translation>加载 PrusaSlicer 打印机配置</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="225"/>
        <source>PrusaSlicer profiles (*.ini);;All files (*)</source>
        <translation>PrusaSlicer 配置 (*.ini);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="240"/>
        <source>Choose a printer profile.</source>
        <translation>请选择打印机配置。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="246"/>
        <source>Slicer settings: %1</source>
        <translation>切片设置：%1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="60"/>
        <source>A plan printed apart is sliced part by part on plates: use Search &gt; Print apart... or &apos;multidir apart&apos; (docs/apart.md).</source>
        <translation>分开打印的方案需逐个零件在打印板上切片：请使用“搜索 &gt; 分开打印...”或“multidir apart”（docs/apart.md）。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceJobRunner</name>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="52"/>
        <source>Slicing step %1 of %2</source>
        <translation>正在切片步骤 %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="54"/>
        <source>Slicing the whole model along up with the slicer&apos;s supports, for comparison</source>
        <translation>正在沿向上方向用切片软件的支撑对整个模型切片，用于比较</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="56"/>
        <source>Stitching the steps into one program</source>
        <translation>正在将各步骤拼接为一个程序</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="60"/>
        <source>Reading the G-code for the preview</source>
        <translation>正在读取 G 代码以供预览</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="66"/>
        <source>The slicer &apos;%1&apos; was not found: install PrusaSlicer (scripts/install-deps.sh) or give the slicer program&apos;s full path in the Slice dialog.</source>
        <translation>未找到切片软件“%1”：请安装 PrusaSlicer（scripts/install-deps.sh），或在“对方案切片”对话框中填写切片程序的完整路径。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="71"/>
        <source>The slicer failed: its command and last output lines are below.</source>
        <translation>切片软件运行失败：其命令和最后几行输出见下方。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="73"/>
        <source>The part does not fit this printer, so nothing was sliced: by how much, and what would help, is below.</source>
        <translation>零件放不进这台打印机，因此没有切片：超出多少、如何解决见下方。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="77"/>
        <source>The G-code failed MultiDir&apos;s checks and was not kept: the step, line and reason are below.</source>
        <translation>G 代码未通过 MultiDir 的检查，未予保留：步骤、行号和原因见下方。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="105"/>
        <source>A slicing job is already running.</source>
        <translation>已有切片作业正在运行。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="142"/>
        <source>Could not create a temporary folder for the G-code: %1</source>
        <translation>无法为 G 代码创建临时文件夹：%1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="139"/>
        <source>Not enough memory to slice this plan.</source>
        <translation>内存不足，无法对此方案切片。</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="133"/>
        <source>The audit of the G-code failed, so unsupported extrusions are not marked: %1</source>
        <translation>G 代码审核失败，因此未标记无支撑挤出：%1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="139"/>
        <source>Unexpected error while slicing.</source>
        <translation>切片时发生意外错误。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SlicePanel</name>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="44"/>
        <source>Slice...</source>
        <translation>切片...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="46"/>
        <location filename="../ui/panels/slice_panel.cpp" line="153"/>
        <source>Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)</source>
        <translation>将当前方案的每个步骤连同其支撑切片为 G 代码（PrusaSlicer）</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="47"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Print time</source>
        <translation>打印时间</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Filament (m)</source>
        <translation>耗材 (m)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Filament (g)</source>
        <translation>耗材 (g)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="83"/>
        <source>Export G-code...</source>
        <translation>导出 G 代码...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="85"/>
        <source>Write step-NN.gcode, job.gcode (when the firmware turns the platform) and the print job with its estimates into a folder</source>
        <translation>将 step-NN.gcode、job.gcode（由固件转动平台时）以及带估算值的打印作业写入文件夹</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="87"/>
        <source>Preview G-code</source>
        <translation>预览 G 代码</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="90"/>
        <source>Show the toolpaths in place of the regions; click again for the plan view</source>
        <translation>显示打印路径而非区域；再次点击返回方案视图</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="93"/>
        <source>Show the layers printed up to this one (all steps, in printing order)</source>
        <translation>显示截至此层已打印的各层（所有步骤，按打印顺序）</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="98"/>
        <source>The layer&apos;s height: the nozzle&apos;s Z above the platform in its step&apos;s pose</source>
        <translation>该层的高度:在其步骤的姿态下喷嘴高于平台的 Z 值</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="100"/>
        <location filename="../ui/panels/slice_panel.cpp" line="266"/>
        <source>Z %1 mm</source>
        <translation>Z %1 mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="101"/>
        <source>Travel moves</source>
        <translation>空驶移动</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="75"/>
        <source>Extrusion that rests on nothing printed before it, as the audit finds it (multidir audit, check b): drawn in magenta in the G-code preview</source>
        <translation>未落在任何先前打印内容上的挤出（multidir audit 检查 b 的结果）：在 G 代码预览中以品红色绘制</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="228"/>
        <source>Unsupported extrusion: %1 mm (%2 %) in magenta</source>
        <translation>无支撑挤出：%1 mm（%2 %），以品红色显示</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="115"/>
        <source>Layers:</source>
        <translation>层：</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="120"/>
        <source>G-code</source>
        <translation>G 代码</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="147"/>
        <source>Show a plan first: run a search or open a plan.</source>
        <translation>请先显示方案：运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="165"/>
        <source>Starting the slicer...</source>
        <translation>正在启动切片软件...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="188"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="196"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="198"/>
        <source>Total</source>
        <translation>合计</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="198"/>
        <source>Total (%1)</source>
        <translation>合计（%1）</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="201"/>
        <source>Fixed direction, slicer supports</source>
        <translation>固定方向，切片软件支撑</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="203"/>
        <source>The whole model printed along up with PrusaSlicer&apos;s own supports: the comparison</source>
        <translation>整个模型沿向上方向打印并使用 PrusaSlicer 自身的支撑：用于比较</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/slice_panel.cpp" line="209"/>
        <source>Slower than the fixed direction: each of the %n steps starts anew (the platform turns, the nozzle lifts and primes, a first layer on the step&apos;s base), and here that costs more time than the slicer&apos;s supports it avoids.</source>
        <translation>
            <numerusform>比固定方向慢：%n 个步骤中的每一步都要重新开始（平台转动、喷嘴抬起并预挤出、在该步骤的底面上打印第一层），在这里这比它省去的切片器支撑花费更多时间。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceSession</name>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="46"/>
        <location filename="../ui/slicing/slice_session.cpp" line="47"/>
        <source>Slicing failed: %1</source>
        <translation>切片失败：%1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="53"/>
        <source>Slicing cancelled: nothing was written.</source>
        <translation>切片已取消：未写入任何内容。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="54"/>
        <source>Slicing cancelled.</source>
        <translation>切片已取消。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="63"/>
        <source>Show a plan first: run a search or open a plan.</source>
        <translation>请先显示方案：运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="65"/>
        <location filename="../ui/slicing/slice_session.cpp" line="122"/>
        <source>The plan&apos;s supports are still being grown: slice it when they are ready.</source>
        <translation>方案的支撑仍在生成中：请在支撑就绪后再切片。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="78"/>
        <source>The plan changed: slicing was cancelled.</source>
        <translation>方案已更改：切片已取消。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="80"/>
        <source>The plan changed: slice it again for its G-code.</source>
        <translation>方案已更改：请重新切片以获得其 G 代码。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="114"/>
        <source>There is no plan to slice: run a search or open a plan.</source>
        <translation>没有可切片的方案：请运行搜索或打开方案。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="118"/>
        <source>A slicing job is already running.</source>
        <translation>已有切片作业正在运行。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="137"/>
        <source>Slicing without supports although the plan leaves risky area: %1</source>
        <translation>方案仍剩余风险面积，但将不带支撑切片：%1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="138"/>
        <source>no supports were grown for it.</source>
        <translation>未为其生成支撑。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="143"/>
        <source>Slicing the plan for %1...</source>
        <translation>正在为 %1 对方案切片...</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="150"/>
        <source>Cancelling: stopping the slicer...</source>
        <translation>正在取消：正在停止切片软件...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/slicing/slice_session.cpp" line="165"/>
        <source>Sliced for %1: %n step(s), %2 of printing.</source>
        <translation>
            <numerusform>已为 %1 完成切片：%n 个步骤，打印用时 %2。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="169"/>
        <source>Slicing finished.</source>
        <translation>切片完成。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="170"/>
        <source>Slicing finished; the audit failed.</source>
        <translation>切片完成；审核失败。</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="205"/>
        <source>Layer %1 of %2: step %3, its layer %4</source>
        <translation>第 %1 / %2 层：步骤 %3 的第 %4 层</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="211"/>
        <source>There is no G-code to export: slice the plan first.</source>
        <translation>没有可导出的 G 代码：请先对方案切片。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/slicing/slice_session.cpp" line="221"/>
        <source>G-code exported to %1 (%n file(s)).</source>
        <translation>
            <numerusform>G 代码已导出到 %1（%n 个文件）。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="231"/>
        <source>Export G-code to Folder</source>
        <translation>将 G 代码导出到文件夹</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="231"/>
        <source>-gcode</source>
        <translation>-gcode</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="232"/>
        <source>G-code folders (*)</source>
        <translation>G 代码文件夹 (*)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="238"/>
        <location filename="../ui/slicing/slice_session.cpp" line="245"/>
        <source>Export G-code</source>
        <translation>导出 G 代码</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="239"/>
        <source>%1 holds files that are not a MultiDir job (%2 is one).

Write the job into this folder anyway? Files with the job&apos;s names are replaced; the others stay.</source>
        <translation>%1 中有不属于 MultiDir 作业的文件（例如 %2）。

仍然将作业写入此文件夹吗？与作业同名的文件将被替换，其他文件保留。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::StudioDocument</name>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="143"/>
        <source>This job was sliced from another plan than the one shown: slice the plan shown again.</source>
        <translation>此作业是由另一个方案切片得到的,而非当前所示方案:请重新切片当前方案。</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="190"/>
        <source>A print run already holds the device session&apos;s job: stop it before starting another.</source>
        <translation>已有打印运行占用设备会话的作业:请先停止它再开始另一个。</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="194"/>
        <source>There is no plan to run: run a search or open a plan first.</source>
        <translation>没有可运行的方案:请先运行搜索或打开一个方案。</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="163"/>
        <source>These parts were made from another plan than the one shown: print the plan shown apart again.</source>
        <translation>这些零件是由另一个方案而非所示方案生成的：请重新分开打印所示方案。</translation>
    </message>
</context>
<context>
    <name>multidir::ui::StudioStartup</name>
    <message>
        <location filename="../ui/studio_startup.cpp" line="62"/>
        <source>MultiDir Studio: plans multi-directional 3D prints.</source>
        <translation>MultiDir Studio：规划多方向 3D 打印。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="66"/>
        <source>Printing (up) direction of the model: x, -y, +z or a,b,c. Default: +z.</source>
        <translation>模型的打印（向上）方向：x、-y、+z 或 a,b,c。默认：+z。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="67"/>
        <source>direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="69"/>
        <source>Render the window to this PNG file and quit.</source>
        <translation>将窗口渲染到此 PNG 文件后退出。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="69"/>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="70"/>
        <source>Language of the user interface: de, zh_CN or en.</source>
        <translation>界面语言：de、zh_CN 或 en。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="71"/>
        <source>language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="73"/>
        <source>Run a search with the default settings once the model is shown.</source>
        <translation>模型显示后立即以默认设置运行搜索。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="74"/>
        <source>Maximal overhang angle in degrees (0-89).</source>
        <translation>最大悬垂角，单位为度（0-89）。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="75"/>
        <source>degrees</source>
        <translation>度</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="82"/>
        <source>Mesh file (.stl .obj .off .ply) or MultiDir project (.multidir) to open. Default: the first sample.</source>
        <translation>要打开的网格文件（.stl .obj .off .ply）或 MultiDir 项目（.multidir）。默认：第一个示例。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="214"/>
        <source>The search or the project&apos;s plan did not finish within %1 s.</source>
        <translation>搜索或项目方案未在 %1 秒内完成。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="83"/>
        <source>[model]</source>
        <translation>[模型]</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="88"/>
        <source>Try --help for usage.</source>
        <translation>使用 --help 查看用法。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="103"/>
        <source>Give at most one model; got %1.</source>
        <translation>最多只能指定一个模型；收到 %1 个。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="107"/>
        <source>--up: %1</source>
        <translation>--up：%1</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="113"/>
        <source>--lang: &apos;%1&apos; is not available; use de, zh_CN or en.</source>
        <translation>--lang：“%1”不可用；请使用 de、zh_CN 或 en。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="120"/>
        <source>--alpha must be a number from 0 to 89.</source>
        <translation>--alpha 必须是 0 到 89 之间的数。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="125"/>
        <source>--screenshot needs a file name.</source>
        <translation>--screenshot 需要一个文件名。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="206"/>
        <source>The model did not finish loading within %1 s.</source>
        <translation>模型未在 %1 秒内加载完成。</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="228"/>
        <source>No model is shown; the screenshot %1 shows the empty window.</source>
        <translation>未显示任何模型；截图 %1 显示的是空窗口。</translation>
    </message>
</context>
</TS>
