<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>DetectionSteps</name>
    <message>
        <source>B1 – dark regions (1st level, intensity)</source>
        <translation>B1 – 暗部区域（第一层，亮度）</translation>
    </message>
    <message>
        <source>B2 – face regions (2nd level, hue)</source>
        <translation>B2 – 脸部区域（第二层，色相）</translation>
    </message>
    <message>
        <source>B3 – B1 and B2 (for the hair region)</source>
        <translation>B3 – B1 与 B2（用于头发区域）</translation>
    </message>
    <message>
        <source>Face and hair regions</source>
        <translation>脸部与头发区域</translation>
    </message>
    <message>
        <source>Eye-pair candidates and the chosen pair</source>
        <translation>双眼候选与选定的一对</translation>
    </message>
    <message>
        <source>Eyeballs and the 2d square</source>
        <translation>眼球与 2d 正方形</translation>
    </message>
    <message>
        <source>Edges and division lines</source>
        <translation>边缘与分割线</translation>
    </message>
    <message>
        <source>Feature regions</source>
        <translation>五官区域</translation>
    </message>
    <message>
        <source>Feature points (thesis pipeline)</source>
        <translation>特征点（论文流程）</translation>
    </message>
    <message>
        <source>Landmarks</source>
        <translation>关键点</translation>
    </message>
    <message>
        <source>Hair region</source>
        <translation>头发区域</translation>
    </message>
    <message>
        <source>Points, close-up</source>
        <translation>特征点特写</translation>
    </message>
    <message>
        <source>thesis pipeline</source>
        <translation>论文流程</translation>
    </message>
    <message>
        <source>%1, close-up</source>
        <translation>%1，特写</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>MovePointCommand</name>
    <message>
        <source>Move %1</source>
        <translation>移动%1</translation>
    </message>
</context>
<context>
    <name>PointHandle</name>
    <message>
        <source>Control point: animation moves it</source>
        <translation>控制点：动画会移动它</translation>
    </message>
    <message>
        <source>Placed by hand: re-detection keeps it</source>
        <translation>手动放置：重新检测时保留</translation>
    </message>
</context>
<context>
    <name>PoseKeyDrag</name>
    <message>
        <source>Left brow, outer</source>
        <translation>左眉，外侧</translation>
    </message>
    <message>
        <source>Left brow, outer middle</source>
        <translation>左眉，外侧中段</translation>
    </message>
    <message>
        <source>Left brow, inner middle</source>
        <translation>左眉，内侧中段</translation>
    </message>
    <message>
        <source>Left brow, inner</source>
        <translation>左眉，内侧</translation>
    </message>
    <message>
        <source>Right brow, inner</source>
        <translation>右眉，内侧</translation>
    </message>
    <message>
        <source>Right brow, inner middle</source>
        <translation>右眉，内侧中段</translation>
    </message>
    <message>
        <source>Right brow, outer middle</source>
        <translation>右眉，外侧中段</translation>
    </message>
    <message>
        <source>Right brow, outer</source>
        <translation>右眉，外侧</translation>
    </message>
    <message>
        <source>Left upper lid</source>
        <translation>左上眼睑</translation>
    </message>
    <message>
        <source>Left lower lid</source>
        <translation>左下眼睑</translation>
    </message>
    <message>
        <source>Right upper lid</source>
        <translation>右上眼睑</translation>
    </message>
    <message>
        <source>Right lower lid</source>
        <translation>右下眼睑</translation>
    </message>
    <message>
        <source>Left mouth corner</source>
        <translation>左嘴角</translation>
    </message>
    <message>
        <source>Right mouth corner</source>
        <translation>右嘴角</translation>
    </message>
    <message>
        <source>Upper lip</source>
        <translation>上唇</translation>
    </message>
    <message>
        <source>Lower lip</source>
        <translation>下唇</translation>
    </message>
    <message>
        <source>Jaw (moves the lower lip and the chin)</source>
        <translation>下颌（带动下唇与下巴）</translation>
    </message>
    <message>
        <source>Set Pose Key</source>
        <translation>设置姿势关键帧</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>No sound</source>
        <translation>无声音</translation>
    </message>
    <message>
        <source>%1 dB</source>
        <translation>%1 dB</translation>
    </message>
</context>
<context>
    <name>TimelineLayout</name>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Audio</source>
        <translation>音频</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>文稿</translation>
    </message>
    <message>
        <source>Mouth</source>
        <translation>口型</translation>
    </message>
    <message>
        <source>Emotion</source>
        <translation>表情</translation>
    </message>
    <message>
        <source>Blinks</source>
        <translation>眨眼</translation>
    </message>
    <message>
        <source>Head</source>
        <translation>头部</translation>
    </message>
    <message>
        <source>Gaze</source>
        <translation>视线</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>姿势</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Toonface: personal cartoon faces from photos.</source>
        <translation>Toonface：用照片制作个人卡通脸。</translation>
    </message>
    <message>
        <source>A photo or a .toonface project to open.</source>
        <translation>要打开的照片或 .toonface 项目。</translation>
    </message>
    <message>
        <source>Detect faces with METHOD in this session: auto, classic or landmarks.</source>
        <translation>本次会话使用 METHOD 检测人脸：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>unknown detection method &quot;%1&quot; (auto, classic or landmarks)</source>
        <translation>未知的检测方法“%1”（auto、classic 或 landmarks）</translation>
    </message>
</context>
<context>
    <name>toonface</name>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>%1: not a readable image</source>
        <translation>%1：不是可读取的图像</translation>
    </message>
</context>
<context>
    <name>toonface::AnimationEdits</name>
    <message>
        <source>placed after %1, at %2 s (it would have played over it)</source>
        <translation>已放在 %1 之后，位于 %2 秒（否则会与其重叠播放）</translation>
    </message>
    <message>
        <source>replaced %1</source>
        <translation>已替换 %1</translation>
    </message>
    <message>
        <source>plays together with %1</source>
        <translation>与 %1 同时播放</translation>
    </message>
</context>
<context>
    <name>toonface::AppearancePanel</name>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Skin</source>
        <translation>皮肤</translation>
    </message>
    <message>
        <source>Hair</source>
        <translation>头发</translation>
    </message>
    <message>
        <source>Brows</source>
        <translation>眉毛</translation>
    </message>
    <message>
        <source>Eyes</source>
        <translation>眼睛</translation>
    </message>
    <message>
        <source>Irises</source>
        <translation>虹膜</translation>
    </message>
    <message>
        <source>Lips</source>
        <translation>嘴唇</translation>
    </message>
    <message>
        <source>Nose</source>
        <translation>鼻子</translation>
    </message>
    <message>
        <source>Cheeks</source>
        <translation>脸颊</translation>
    </message>
    <message>
        <source>Glasses</source>
        <translation>眼镜</translation>
    </message>
    <message>
        <source>Moustache</source>
        <translation>小胡子</translation>
    </message>
    <message>
        <source>Beard</source>
        <translation>胡须</translation>
    </message>
    <message>
        <source>Hat</source>
        <translation>帽子</translation>
    </message>
    <message>
        <source>Drawing</source>
        <translation>绘制</translation>
    </message>
    <message>
        <source>Cute proportions</source>
        <translation>可爱比例</translation>
    </message>
    <message>
        <source>How much the drawing exaggerates what makes this face its own (0 = exact)</source>
        <translation>绘图夸张这张脸独有特征的程度（0 = 写实）</translation>
    </message>
    <message>
        <source>Eyebrows:</source>
        <translation>眉毛：</translation>
    </message>
    <message>
        <source>Nose:</source>
        <translation>鼻子：</translation>
    </message>
    <message>
        <source>Caricature:</source>
        <translation>夸张程度：</translation>
    </message>
    <message>
        <source>Worn and grown</source>
        <translation>佩戴与毛发</translation>
    </message>
    <message>
        <source>Bald head</source>
        <translation>光头</translation>
    </message>
    <message>
        <source>Glasses:</source>
        <translation>眼镜：</translation>
    </message>
    <message>
        <source>Resample colours from the photo</source>
        <translation>从照片重新取色</translation>
    </message>
    <message>
        <source>Skin, hair, eyes and lips from the photo (its colour cast taken out), and what the person wears</source>
        <translation>从照片获取皮肤、头发、眼睛和嘴唇的颜色（去除色偏），以及人物的穿戴</translation>
    </message>
    <message>
        <source>Eyebrows</source>
        <translation>眉毛</translation>
    </message>
    <message>
        <source>Cute</source>
        <translation>可爱</translation>
    </message>
    <message>
        <source>Caricature</source>
        <translation>夸张程度</translation>
    </message>
    <message>
        <source>Resample colours</source>
        <translation>重新取色</translation>
    </message>
    <message>
        <source>Colours and lines</source>
        <translation>颜色与线条</translation>
    </message>
    <message>
        <source>Shown</source>
        <translation>显示</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>填充</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>线条</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>粗细</translation>
    </message>
    <message>
        <source>Line weight in hundredths of the eye distance</source>
        <translation>线条粗细，以双眼距离的百分之一为单位</translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation>显示%1</translation>
    </message>
    <message>
        <source>Line weight</source>
        <translation>线条粗细</translation>
    </message>
    <message>
        <source>Line colour</source>
        <translation>线条颜色</translation>
    </message>
    <message>
        <source>Fill colour</source>
        <translation>填充颜色</translation>
    </message>
    <message>
        <source>Neck and shoulders</source>
        <translation>脖子和肩膀</translation>
    </message>
    <message>
        <source>Expression lines</source>
        <translation>表情纹</translation>
    </message>
    <message>
        <source>Smile blush</source>
        <translation>微笑腮红</translation>
    </message>
    <message>
        <source>Your layers</source>
        <translation>你的图层</translation>
    </message>
    <message>
        <source>Goatee</source>
        <translation>山羊胡</translation>
    </message>
    <message>
        <source>Hair on the chin only (drawn when there is no beard)</source>
        <translation>只在下巴上的胡子（没有胡须时才画出）</translation>
    </message>
    <message>
        <source>A child is drawn with thin light brows, unpainted lips, a rounder jaw and larger eyes; an elderly person with fine age lines</source>
        <translation>儿童画成细淡的眉毛、不涂色的嘴唇、较圆的下颌和较大的眼睛；老人画上细细的皱纹</translation>
    </message>
    <message>
        <source>Adult</source>
        <translation>成人</translation>
    </message>
    <message>
        <source>Child</source>
        <translation>儿童</translation>
    </message>
    <message>
        <source>Elderly</source>
        <translation>老人</translation>
    </message>
    <message>
        <source>Age:</source>
        <translation>年龄：</translation>
    </message>
    <message>
        <source>Age</source>
        <translation>年龄</translation>
    </message>
</context>
<context>
    <name>toonface::ApplyDetection</name>
    <message>
        <source>Use another face</source>
        <translation>使用另一张脸</translation>
    </message>
    <message>
        <source>Detect face</source>
        <translation>检测人脸</translation>
    </message>
    <message>
        <source>Sample colours</source>
        <translation>采样颜色</translation>
    </message>
    <message>
        <source>Re-detect keeping my points</source>
        <translation>重新检测并保留我的特征点</translation>
    </message>
    <message>
        <source>Re-detect points</source>
        <translation>重新检测特征点</translation>
    </message>
    <message>
        <source>Face found by the %1 method in %2 ms.</source>
        <translation>用 %1 方法找到人脸，耗时 %2 毫秒。</translation>
    </message>
    <message numerus="yes">
        <source>%n faces found: using the one you chose (%1, %2 ms).</source>
        <translation>
            <numerusform>找到 %n 张脸：使用您选择的那张（%1，%2 毫秒）。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n faces found: using the largest, most central one (%1, %2 ms). Click another face&apos;s box to switch.</source>
        <translation>
            <numerusform>找到 %n 张脸：使用最大、最居中的那张（%1，%2 毫秒）。单击其他脸的方框即可切换。</numerusform>
        </translation>
    </message>
    <message>
        <source>The landmark method could not serve: %1</source>
        <translation>关键点方法无法使用：%1</translation>
    </message>
    <message>
        <source>The face is turned about %1° to the side.</source>
        <translation>脸转向一侧约 %1°。</translation>
    </message>
    <message>
        <source>The head is tilted about %1°.</source>
        <translation>头倾斜约 %1°。</translation>
    </message>
    <message>
        <source>The cartoon is drawn from the front and will look twisted: a photo looking straight into the camera works best.</source>
        <translation>卡通是从正面画的，会显得扭曲：正面直视镜头的照片效果最好。</translation>
    </message>
</context>
<context>
    <name>toonface::Autosaver</name>
    <message>
        <source>%1: cannot write the recovery file: %2</source>
        <translation>%1：无法写入恢复文件：%2</translation>
    </message>
    <message>
        <source>%1: cannot write the recovery file</source>
        <translation>%1：无法写入恢复文件</translation>
    </message>
</context>
<context>
    <name>toonface::BlinksDialog</name>
    <message>
        <source>&amp;From</source>
        <translation>从(&amp;F)</translation>
    </message>
    <message>
        <source>Add Blinks</source>
        <translation>添加眨眼</translation>
    </message>
    <message>
        <source>The &amp;whole animation (%1 s)</source>
        <translation>整段动画（%1 秒）(&amp;W)</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source>Over:</source>
        <translation>范围：</translation>
    </message>
    <message>
        <source>The range ends before it starts.</source>
        <translation>范围的结束早于开始。</translation>
    </message>
    <message numerus="yes">
        <source>%n blink(s) from %1 s to %2 s.</source>
        <translation>
            <numerusform>从 %1 秒到 %2 秒共 %n 次眨眼。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The %n blink(s) there now are replaced.</source>
        <translation>
            <numerusform>此范围原有的 %n 次眨眼将被替换。</numerusform>
        </translation>
    </message>
    <message>
        <source>Blinks at a person&apos;s pace: about one every three and a half seconds, now and then two in a row. The same pattern number always gives the same blinks.</source>
        <translation>以真人的节奏眨眼：大约每三秒半一次，偶尔连续两次。同一个样式编号总是产生相同的眨眼。</translation>
    </message>
    <message>
        <source>&amp;Shuffle</source>
        <translation>随机(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Pattern:</source>
        <translation>样式(&amp;P)：</translation>
    </message>
</context>
<context>
    <name>toonface::BookDialog</name>
    <message>
        <source>Export Read-aloud Book</source>
        <translation>导出有声书</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>&amp;Text:</source>
        <translation>文字(&amp;T)：</translation>
    </message>
    <message>
        <source>Text (*.txt *.md *.markdown)</source>
        <translation>文字 (*.txt *.md *.markdown)</translation>
    </message>
    <message>
        <source>A recording of the text</source>
        <translation>这段文字的录音</translation>
    </message>
    <message>
        <source>The built-in voice</source>
        <translation>内置语音</translation>
    </message>
    <message>
        <source>&amp;Read by:</source>
        <translation>朗读者(&amp;R)：</translation>
    </message>
    <message>
        <source>&amp;Recording:</source>
        <translation>录音(&amp;R)：</translation>
    </message>
    <message>
        <source>Sound (*.wav *.flac *.mp3 *.ogg *.opus *.m4a)</source>
        <translation>声音 (*.wav *.flac *.mp3 *.ogg *.opus *.m4a)</translation>
    </message>
    <message>
        <source>As the text reads</source>
        <translation>依文字判断</translation>
    </message>
    <message>
        <source>Chinese (Traditional)</source>
        <translation>中文（繁体）</translation>
    </message>
    <message>
        <source>Chinese (Simplified)</source>
        <translation>中文（简体）</translation>
    </message>
    <message>
        <source>English</source>
        <translation>英文</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <source>The first heading, or the text&apos;s file name</source>
        <translation>第一个标题，或文字的文件名</translation>
    </message>
    <message>
        <source>T&amp;itle:</source>
        <translation>书名(&amp;I)：</translation>
    </message>
    <message>
        <source>&amp;Author:</source>
        <translation>作者(&amp;A)：</translation>
    </message>
    <message>
        <source>Each sentence</source>
        <translation>每一句</translation>
    </message>
    <message>
        <source>Each character or word</source>
        <translation>每个字或单词</translation>
    </message>
    <message>
        <source>&amp;Highlight:</source>
        <translation>标示(&amp;H)：</translation>
    </message>
    <message>
        <source>&amp;Book:</source>
        <translation>书(&amp;B)：</translation>
    </message>
    <message>
        <source>EPUB book (*.epub)</source>
        <translation>EPUB 书 (*.epub)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <source>Export Read-aloud &amp;Book…</source>
        <translation>导出有声书(&amp;B)…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>正在开始…</translation>
    </message>
    <message numerus="yes">
        <source>Wrote %1: %n page(s)</source>
        <translation>
            <numerusform>已写入 %1：%n 页</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled; nothing was written.</source>
        <translation>已取消；没有写入任何文件。</translation>
    </message>
    <message numerus="yes">
        <source>The project&apos;s audio track (%n recording(s), mixed)</source>
        <translation>
            <numerusform>项目的音轨（%n 段录音，混音）</numerusform>
        </translation>
    </message>
    <message>
        <source>Mixing the recordings…</source>
        <translation>正在混合录音…</translation>
    </message>
    <message>
        <source>An animated drawing</source>
        <translation>一张动画图</translation>
    </message>
    <message>
        <source>A video of each page</source>
        <translation>每一页的视频</translation>
    </message>
    <message>
        <source>A video of each page read aloud plays in reading systems that neither read aloud nor animate drawings; it takes longer to make</source>
        <translation>每一页朗读的视频可在既不会朗读、也不会播放动画图的阅读器中播放；制作需要较长时间</translation>
    </message>
    <message>
        <source>&amp;Face:</source>
        <translation>脸(&amp;F)：</translation>
    </message>
</context>
<context>
    <name>toonface::CameraFeed</name>
    <message>
        <source>No camera was found on this computer. Connect a camera and try again, or open a photo (File ▸ Open) or a video instead.</source>
        <translation>这台电脑上找不到摄像头。请连接摄像头后重试，或改为打开照片（文件 ▸ 打开）或视频。</translation>
    </message>
    <message>
        <source>The camera “%1” stopped: %2</source>
        <translation>摄像头“%1”已停止：%2</translation>
    </message>
    <message>
        <source>The camera “%1” was disconnected.</source>
        <translation>摄像头“%1”已断开连接。</translation>
    </message>
</context>
<context>
    <name>toonface::CaptureDialog</name>
    <message>
        <source>&amp;Take Photo in 3 s</source>
        <translation>3 秒后拍照(&amp;T)</translation>
    </message>
    <message>
        <source>Capture from Camera</source>
        <translation>从摄像头拍摄</translation>
    </message>
    <message>
        <source>Look straight at the camera with a relaxed face, mouth closed: the photo becomes the neutral face</source>
        <translation>放松面部、闭上嘴巴，直视摄像头：这张照片将成为中性脸</translation>
    </message>
    <message>
        <source>&amp;Camera:</source>
        <translation>摄像头(&amp;C)：</translation>
    </message>
    <message>
        <source>No camera</source>
        <translation>没有摄像头</translation>
    </message>
    <message>
        <source>No face in view yet.</source>
        <translation>画面中还没有人脸。</translation>
    </message>
    <message>
        <source>Face found: keep still and take the photo.</source>
        <translation>找到人脸：请保持不动并拍照。</translation>
    </message>
    <message>
        <source>Starting the camera…</source>
        <translation>正在启动摄像头…</translation>
    </message>
    <message>
        <source>Camera “%1”</source>
        <translation>摄像头“%1”</translation>
    </message>
    <message>
        <source>The camera has not shown a picture yet.</source>
        <translation>摄像头尚未显示任何画面。</translation>
    </message>
    <message>
        <source>%1: the photo cannot be written</source>
        <translation>%1：无法写入照片</translation>
    </message>
</context>
<context>
    <name>toonface::CartoonFile</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1：无法写入：%2</translation>
    </message>
    <message>
        <source>%1: no image format: give the file a suffix (.svg, .png)</source>
        <translation>%1：没有图像格式：请为文件加上扩展名（.svg、.png）</translation>
    </message>
    <message>
        <source>%1: the cartoon could not be drawn</source>
        <translation>%1：无法绘制卡通</translation>
    </message>
    <message>
        <source>%1: cannot encode the image as %2</source>
        <translation>%1：无法将图像编码为 %2</translation>
    </message>
</context>
<context>
    <name>toonface::DetectionStepsUi</name>
    <message>
        <source>Detection &amp;Steps</source>
        <translation>检测步骤(&amp;S)</translation>
    </message>
    <message>
        <source>Step:</source>
        <translation>步骤：</translation>
    </message>
    <message>
        <source>Opacity:</source>
        <translation>不透明度：</translation>
    </message>
    <message>
        <source>How strongly the detection step covers the photo</source>
        <translation>检测步骤覆盖照片的浓淡程度</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>无(&amp;N)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Draw “%1” over the photo (%2.png with --debug-dir)</source>
        <translation>在照片上绘制“%1”（使用 --debug-dir 时为 %2.png）</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Show “%1” in a window of its own (%2.png with --debug-dir)</source>
        <translation>在独立窗口中显示“%1”（使用 --debug-dir 时为 %2.png）</translation>
    </message>
    <message>
        <source>Show an intermediate image of the face detection over the photo</source>
        <translation>在照片上显示人脸检测的中间图像</translation>
    </message>
</context>
<context>
    <name>toonface::Detector</name>
    <message>
        <source>No face was found in the image (%1 x %2 pixels). A frontal, upright face at least %3 pixels wide is needed.</source>
        <translation>在图像（%1 x %2 像素）中找不到人脸。需要一张正面、端正且至少 %3 像素宽的人脸。</translation>
    </message>
    <message>
        <source>The image (%1 x %2 pixels) is too small to hold a face.</source>
        <translation>图像（%1 x %2 像素）太小，容纳不下一张人脸。</translation>
    </message>
    <message>
        <source>there is no cache yet</source>
        <translation>还没有缓存</translation>
    </message>
    <message>
        <source>the cache could not be opened: %1</source>
        <translation>无法打开缓存：%1</translation>
    </message>
    <message>
        <source>the cache is cut short</source>
        <translation>缓存不完整（文件被截断）</translation>
    </message>
    <message>
        <source>the file is not a cache of this kind</source>
        <translation>此文件不是这一类的缓存</translation>
    </message>
    <message>
        <source>the cache is of another version (%1)</source>
        <translation>缓存属于另一个版本（%1）</translation>
    </message>
    <message>
        <source>the cache was made from another model</source>
        <translation>缓存是由另一个模型生成的</translation>
    </message>
    <message>
        <source>the cache is %1 bytes, not the %2 its header gives</source>
        <translation>缓存有 %1 字节，而不是文件头记载的 %2</translation>
    </message>
    <message>
        <source>the cache could not be read: %1</source>
        <translation>无法读取缓存：%1</translation>
    </message>
    <message>
        <source>the cache is damaged (its checksum does not match)</source>
        <translation>缓存已损坏（校验和不符）</translation>
    </message>
    <message>
        <source>the folder %1 could not be made</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>The image is too small for the classic method.</source>
        <translation>图像太小，无法使用经典方法。</translation>
    </message>
    <message>
        <source>No eye pair was found (the classic method needs a large frontal face on a plain background).</source>
        <translation>找不到一对眼睛（经典方法需要纯色背景前的大幅正面人脸）。</translation>
    </message>
    <message>
        <source>the point between the eyes is not in the face region</source>
        <translation>两眼之间的点不在人脸区域内</translation>
    </message>
    <message>
        <source>the face region reaches %1 eye distances below it (%2 needed)</source>
        <translation>人脸区域向下只延伸 %1 个眼距（需要 %2）</translation>
    </message>
    <message>
        <source>%1 eye distances to its nearer side (%2 .. %3 needed)</source>
        <translation>到较近一侧的距离为 %1 个眼距（需要 %2 .. %3）</translation>
    </message>
    <message>
        <source>no mouth row below it (the darkest row is %1% darker than the median, %2% needed)</source>
        <translation>下方没有嘴巴所在的行（最暗的行比中位数暗 %1%，需要 %2%）</translation>
    </message>
    <message>
        <source>the best eye pair by eq. (3.5), at (%1, %2) and (%3, %4), has no face around it: %5</source>
        <translation>按式 (3.5) 最佳的一对眼睛位于 (%1, %2) 和 (%3, %4)，但周围没有人脸：%5</translation>
    </message>
    <message>
        <source>The classic method found an eye pair but could not place a face around it (a feature collapsed to nothing).</source>
        <translation>经典方法找到了一对眼睛，但无法在其周围放置人脸（有个特征缩成了零）。</translation>
    </message>
    <message>
        <source>The classic method found no face: %1.</source>
        <translation>经典方法找不到人脸：%1。</translation>
    </message>
    <message>
        <source>Face detection was cancelled.</source>
        <translation>人脸检测已取消。</translation>
    </message>
    <message>
        <source>The image is empty.</source>
        <translation>图像是空的。</translation>
    </message>
    <message>
        <source>the cache is damaged (it holds no detector)</source>
        <translation>缓存已损坏（其中没有检测器）</translation>
    </message>
    <message>
        <source>the cache is damaged (%1)</source>
        <translation>缓存已损坏（%1）</translation>
    </message>
    <message>
        <source>no face to search around</source>
        <translation>没有可供搜索周围的人脸</translation>
    </message>
    <message>
        <source>the face is too small</source>
        <translation>人脸太小</translation>
    </message>
    <message>
        <source>the head is outside the photo</source>
        <translation>头部超出照片范围</translation>
    </message>
    <message>
        <source>the face is outside the photo</source>
        <translation>人脸超出照片范围</translation>
    </message>
    <message>
        <source>the face&apos;s central rectangle is dark</source>
        <translation>人脸中央的矩形太暗</translation>
    </message>
    <message>
        <source>the face region misses the face</source>
        <translation>人脸区域没有覆盖人脸</translation>
    </message>
    <message>
        <source>the head&apos;s outline could not be followed (%1 of %2 searches ended on it)</source>
        <translation>无法沿着头部轮廓跟踪（%2 次搜索中只有 %1 次停在轮廓上）</translation>
    </message>
    <message>
        <source>no { } block of points</source>
        <translation>没有 { } 点块</translation>
    </message>
    <message>
        <source>%1 numbers where %2 coordinates were expected</source>
        <translation>有 %1 个数字，但应有 %2 个坐标</translation>
    </message>
    <message>
        <source>point %1 is not two numbers</source>
        <translation>第 %1 个点不是两个数字</translation>
    </message>
    <message>
        <source>is missing (install the package libdlib-data, or set TOONFACE_LANDMARK_MODEL to shape_predictor_68_face_landmarks.dat).</source>
        <translation>不存在（请安装 libdlib-data 软件包，或将 TOONFACE_LANDMARK_MODEL 设为 shape_predictor_68_face_landmarks.dat）。</translation>
    </message>
    <message>
        <source>The landmark model %1 %2</source>
        <translation>关键点模型 %1 %2</translation>
    </message>
    <message>
        <source>could not be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>could not be opened.</source>
        <translation>无法打开。</translation>
    </message>
    <message>
        <source>gives %1 points, not the 68 of the iBUG scheme.</source>
        <translation>有 %1 个点，而不是 iBUG 规范的 68 个。</translation>
    </message>
    <message>
        <source>could not be read: %1 at byte %2</source>
        <translation>无法读取：%1（在第 %2 字节）</translation>
    </message>
    <message>
        <source>could not be read: it ends early (at byte %1, in the middle of the model)</source>
        <translation>无法读取：文件提前结束（在第 %1 字节，模型的中途）</translation>
    </message>
    <message>
        <source>could not be read: no memory for it (%1)</source>
        <translation>无法读取：内存不足（%1）</translation>
    </message>
    <message>
        <source>could not be opened: %1</source>
        <translation>无法打开：%1</translation>
    </message>
</context>
<context>
    <name>toonface::Document</name>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>Untitled project</source>
        <translation>未命名项目</translation>
    </message>
</context>
<context>
    <name>toonface::EmotionDialog</name>
    <message>
        <source>The emotions already there &amp;give way</source>
        <translation>让已有的表情让位(&amp;G)</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>添加表情</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>in</source>
        <translation>淡入</translation>
    </message>
    <message>
        <source>out</source>
        <translation>淡出</translation>
    </message>
    <message>
        <source>Otherwise the new emotion adds to the ones under it</source>
        <translation>否则新表情会叠加在下方的表情上</translation>
    </message>
    <message>
        <source>&amp;Emotion:</source>
        <translation>表情(&amp;E)：</translation>
    </message>
    <message>
        <source>&amp;From:</source>
        <translation>从(&amp;F)：</translation>
    </message>
    <message>
        <source>&amp;Intensity:</source>
        <translation>强度(&amp;I)：</translation>
    </message>
    <message>
        <source>Fade:</source>
        <translation>淡入淡出：</translation>
    </message>
    <message>
        <source>Add Emotion (%1)</source>
        <translation>添加表情（%1）</translation>
    </message>
</context>
<context>
    <name>toonface::EmotionPalette</name>
    <message>
        <source>%1: click to apply to the selection (or 2 s from the playhead), or drag onto the emotion track</source>
        <translation>%1：单击应用到所选范围（或从播放头起 2 秒），或拖动到表情轨道</translation>
    </message>
</context>
<context>
    <name>toonface::Export</name>
    <message>
        <source>no output file given</source>
        <translation>没有指定输出文件</translation>
    </message>
    <message>
        <source>unsupported size %1 (from %2 to %3 pixels)</source>
        <translation>不支持的尺寸 %1（应为 %2 到 %3 像素）</translation>
    </message>
    <message>
        <source>unsupported frame rate %1 (more than 0, up to %2)</source>
        <translation>不支持的帧率 %1（应大于 0，最多 %2）</translation>
    </message>
    <message>
        <source>cannot write: the folder %1 does not exist</source>
        <translation>无法写入：文件夹 %1 不存在</translation>
    </message>
    <message>
        <source>cannot write PNG frames: it is a file, not a folder</source>
        <translation>无法写入 PNG 帧：这是文件，不是文件夹</translation>
    </message>
    <message>
        <source>cannot write: it is a folder</source>
        <translation>无法写入：这是文件夹</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>无法写入：%1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>cannot write: cannot create a folder in %1</source>
        <translation>无法写入：无法在 %1 中创建文件夹</translation>
    </message>
    <message>
        <source>rendering stopped</source>
        <translation>渲染已停止</translation>
    </message>
    <message>
        <source>cannot write GIF: FFmpeg has no GIF encoder</source>
        <translation>无法写入 GIF：FFmpeg 没有 GIF 编码器</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (GIF takes 1 to 65535 pixels a side)</source>
        <translation>不支持的尺寸 %1x%2（GIF 每边须为 1 到 65535 像素）</translation>
    </message>
    <message>
        <source>cannot start the GIF encoder: %1</source>
        <translation>无法启动 GIF 编码器：%1</translation>
    </message>
    <message>
        <source>out of memory for a %1x%2 frame</source>
        <translation>内存不足，无法容纳 %1x%2 的帧</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>内存不足</translation>
    </message>
    <message>
        <source>cannot write MP4: FFmpeg has no H.264 encoder (libx264)</source>
        <translation>无法写入 MP4：FFmpeg 没有 H.264 编码器（libx264）</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (MP4 takes 2 to 8192 pixels a side)</source>
        <translation>不支持的尺寸 %1x%2（MP4 每边须为 2 到 8192 像素）</translation>
    </message>
    <message>
        <source>cannot start the H.264 encoder at %1x%2: %3</source>
        <translation>无法以 %1x%2 启动 H.264 编码器：%3</translation>
    </message>
    <message>
        <source>cannot convert %1x%2 RGB to YUV</source>
        <translation>无法将 %1x%2 的 RGB 转换为 YUV</translation>
    </message>
    <message>
        <source>cannot write MP4: FFmpeg has no AAC encoder</source>
        <translation>无法写入 MP4：FFmpeg 没有 AAC 编码器</translation>
    </message>
    <message>
        <source>the writer is closed</source>
        <translation>写入器已关闭</translation>
    </message>
    <message>
        <source>cannot write in the folder %1: %2</source>
        <translation>无法写入文件夹 %1：%2</translation>
    </message>
    <message>
        <source>FFmpeg has no %1 muxer: %2</source>
        <translation>FFmpeg 没有 %1 封装器：%2</translation>
    </message>
    <message>
        <source>cannot write the header: %1</source>
        <translation>无法写入文件头：%1</translation>
    </message>
    <message>
        <source>cannot set up the stream: %1</source>
        <translation>无法配置流：%1</translation>
    </message>
    <message>
        <source>cannot encode (%1): %2</source>
        <translation>无法编码（%1）：%2</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (PNG frames take 1 to 32768 pixels a side)</source>
        <translation>不支持的尺寸 %1x%2（PNG 帧每边须为 1 到 32768 像素）</translation>
    </message>
    <message>
        <source>cannot create the folder for PNG frames</source>
        <translation>无法创建存放 PNG 帧的文件夹</translation>
    </message>
    <message>
        <source>unexpected head transform &apos;%1&apos;</source>
        <translation>意外的头部变换“%1”</translation>
    </message>
    <message>
        <source>the drawing has no head group</source>
        <translation>绘图中没有头部分组</translation>
    </message>
    <message>
        <source>the drawing changes its structure with the pose</source>
        <translation>绘图的结构会随姿势改变</translation>
    </message>
    <message>
        <source>the drawing is not valid XML: %1</source>
        <translation>绘图不是有效的 XML：%1</translation>
    </message>
    <message>
        <source>the writer is already writing %1</source>
        <translation>写入器正在写入 %1</translation>
    </message>
    <message>
        <source>unsupported frame rate %1 (expected more than 0, up to 240)</source>
        <translation>不支持的帧率 %1（应大于 0，最多 240）</translation>
    </message>
    <message>
        <source>unsupported size %1x%2</source>
        <translation>不支持的尺寸 %1x%2</translation>
    </message>
    <message>
        <source>the writer is not open</source>
        <translation>写入器尚未打开</translation>
    </message>
    <message>
        <source>an earlier frame failed; cancel the writer</source>
        <translation>先前的帧失败了，请取消写入</translation>
    </message>
    <message>
        <source>frame %1 is %2x%3, the video is %4x%5</source>
        <translation>第 %1 帧为 %2x%3，但视频为 %4x%5</translation>
    </message>
    <message>
        <source>an earlier frame failed; nothing was written</source>
        <translation>先前的帧失败了，没有写入任何内容</translation>
    </message>
    <message>
        <source>no frames to write</source>
        <translation>没有可写入的帧</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>is not UTF-8 text</source>
        <translation>不是 UTF-8 文字</translation>
    </message>
    <message>
        <source>unknown book language &apos;%1&apos; (%2)</source>
        <translation>未知的书籍语言“%1”（%2）</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1，第 %2 行</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be read aloud: %2</source>
        <translation>“%1”无法朗读：%2</translation>
    </message>
    <message>
        <source>no room for temporary files: %1</source>
        <translation>没有空间存放临时文件：%1</translation>
    </message>
    <message>
        <source>reading the recording</source>
        <translation>正在读取录音</translation>
    </message>
    <message>
        <source>the recording (%1 s) is shorter than the text: its %2 words need at least %3 s even read fast (%4 a second)</source>
        <translation>录音（%1 秒）比文字短：文字的 %2 个单词即使读得很快（每秒 %4 个）也至少需要 %3 秒</translation>
    </message>
    <message>
        <source>the recording (%1 s) is shorter than the text: its %2 syllables need at least %3 s even read fast (%4 a second)</source>
        <translation>录音（%1 秒）比文字短：文字的 %2 个音节即使读得很快（每秒 %4 个）也至少需要 %3 秒</translation>
    </message>
    <message>
        <source>aligning the recording with the text</source>
        <translation>正在将录音与文字对齐</translation>
    </message>
    <message>
        <source>%1 and %2 could not be aligned: syllables were lost</source>
        <translation>%1 与 %2 无法对齐：丢失了音节</translation>
    </message>
    <message>
        <source>cannot write beside it</source>
        <translation>无法在其旁边写入</translation>
    </message>
    <message>
        <source>cannot draw the cover</source>
        <translation>无法绘制封面</translation>
    </message>
    <message>
        <source>drawing the pages</source>
        <translation>正在绘制页面</translation>
    </message>
    <message>
        <source>reading chapter %1 of %2 aloud</source>
        <translation>正在朗读第 %1 章（共 %2 章）</translation>
    </message>
    <message>
        <source>the voice lost syllables of chapter %1</source>
        <translation>语音丢失了第 %1 章的音节</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>the text is empty: there is nothing to read</source>
        <translation>文字是空的：没有可朗读的内容</translation>
    </message>
    <message>
        <source>no sentence ends anywhere in the text: end its sentences with . ! ? or 。！？ so that the book can highlight them as they are read</source>
        <translation>文字中没有任何句子结尾：请以 . ! ? 或 。！？ 结束句子，书才能在朗读时标示它们</translation>
    </message>
    <message>
        <source>the book is too large for a ZIP archive (4 GiB, 65535 files)</source>
        <translation>书太大，无法放进 ZIP 压缩包（4 GiB、65535 个文件）</translation>
    </message>
    <message>
        <source>cannot compress %1</source>
        <translation>无法压缩 %1</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>the drawing is nested more than %1 levels deep</source>
        <translation>绘图的嵌套层级超过 %1 层</translation>
    </message>
    <message>
        <source>cannot write %1: FFmpeg has no %2 encoder</source>
        <translation>无法写入 %1：FFmpeg 没有 %2 编码器</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (%3 takes 2 to 8192 pixels a side)</source>
        <translation>不支持的尺寸 %1x%2（%3 每边需 2 到 8192 像素）</translation>
    </message>
    <message>
        <source>cannot start the %1 encoder at %2x%3: %4</source>
        <translation>无法以 %2x%3 启动 %1 编码器：%4</translation>
    </message>
    <message>
        <source>cannot convert %1x%2 RGBA for %3</source>
        <translation>无法为 %3 转换 %1x%2 的 RGBA</translation>
    </message>
    <message>
        <source>the start (%1 s) and duration (%2 s) must be 0 or more</source>
        <translation>开始（%1 秒）与长度（%2 秒）必须为 0 或以上</translation>
    </message>
    <message>
        <source>SVG and HTML play the whole animation; a start or duration needs a video or picture format</source>
        <translation>SVG 与 HTML 会播放整段动画；开始或长度需要视频或图片格式</translation>
    </message>
    <message>
        <source>the start (%1 s) is past the end of the animation (%2 s)</source>
        <translation>开始（%1 秒）已超过动画结尾（%2 秒）</translation>
    </message>
    <message>
        <source>MP4 cannot be transparent: choose WebM, MOV, WebP, APNG, GIF or PNG frames, or a background colour or photo</source>
        <translation>MP4 无法透明：请选择 WebM、MOV、WebP、APNG、GIF 或 PNG 帧，或选择背景颜色或照片</translation>
    </message>
    <message>
        <source>SVG and HTML are drawn without a background; a background colour or photo needs a video or picture format</source>
        <translation>SVG 与 HTML 不绘制背景；背景颜色或照片需要视频或图片格式</translation>
    </message>
    <message>
        <source>the background colour is not valid</source>
        <translation>背景颜色无效</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a background: give a colour (a name such as white, or #rrggbb), transparent, or an existing image file</source>
        <translation>“%1”不是背景：请给颜色（例如 white 这样的名称，或 #rrggbb）、transparent，或现有的图像文件</translation>
    </message>
    <message>
        <source>the %1 preset writes %2: name the output .%3</source>
        <translation>%1 预设会写出 %2：请将输出命名为 .%3</translation>
    </message>
    <message>
        <source>the clip is %1 s long, the %2 preset allows %3 s (%4 s too long): export a stretch of at most %3 s</source>
        <translation>片段长 %1 秒，%2 预设最多 %3 秒（超出 %4 秒）：请导出最多 %3 秒的一段</translation>
    </message>
    <message>
        <source>at the lowest quality the file is %1 KB, the %2 preset allows %3 KB (%4 KB over): export a shorter stretch or a lower frame rate</source>
        <translation>即使最低画质，文件仍有 %1 KB，%2 预设最多 %3 KB（超出 %4 KB）：请导出较短的一段或较低的帧率</translation>
    </message>
    <message>
        <source>cannot write: the GIF encoder wrote an unexpected file</source>
        <translation>无法写入：GIF 编码器写出了非预期的文件</translation>
    </message>
    <message>
        <source>cannot start the %1 encoder: %2</source>
        <translation>无法启动 %1 编码器：%2</translation>
    </message>
    <message>
        <source>no sound to cut the page&apos;s video from</source>
        <translation>没有可剪出该页视频的声音</translation>
    </message>
</context>
<context>
    <name>toonface::ExportAnimationDialog</name>
    <message>
        <source>SVG animation (SMIL)</source>
        <translation>SVG 动画（SMIL）</translation>
    </message>
    <message>
        <source>HTML player</source>
        <translation>HTML 播放器</translation>
    </message>
    <message>
        <source>MP4 video</source>
        <translation>MP4 视频</translation>
    </message>
    <message>
        <source>Animated GIF</source>
        <translation>GIF 动画</translation>
    </message>
    <message>
        <source>PNG sequence (a folder of frames)</source>
        <translation>PNG 序列（一个存放帧的文件夹）</translation>
    </message>
    <message>
        <source>SVG animation (*.svg)</source>
        <translation>SVG 动画 (*.svg)</translation>
    </message>
    <message>
        <source>HTML page (*.html *.htm)</source>
        <translation>HTML 网页 (*.html *.htm)</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4 视频 (*.mp4)</translation>
    </message>
    <message>
        <source>Animated GIF (*.gif)</source>
        <translation>GIF 动画 (*.gif)</translation>
    </message>
    <message>
        <source>Folder for the frames (*)</source>
        <translation>帧文件夹 (*)</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation>导出动画</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Choose where to save the animation</source>
        <translation>选择动画的保存位置</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>%1 px</source>
        <translation>%1 像素</translation>
    </message>
    <message>
        <source>The longer side of the video frames; the drawing is vector, so any size is sharp</source>
        <translation>视频画面的长边；绘图是矢量图，任何尺寸都清晰</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>The head</source>
        <translation>头部</translation>
    </message>
    <message>
        <source>The whole photo</source>
        <translation>整张照片</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>格式(&amp;F)：</translation>
    </message>
    <message>
        <source>&amp;Save to:</source>
        <translation>保存到(&amp;S)：</translation>
    </message>
    <message>
        <source>Frame si&amp;ze:</source>
        <translation>画面大小(&amp;Z)：</translation>
    </message>
    <message>
        <source>Frame &amp;rate:</source>
        <translation>帧率(&amp;R)：</translation>
    </message>
    <message>
        <source>Fr&amp;aming:</source>
        <translation>取景(&amp;A)：</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Show in Folder</source>
        <translation>在文件夹中显示(&amp;S)</translation>
    </message>
    <message>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 已存在。要替换吗？</translation>
    </message>
    <message>
        <source>Exporting to %1…</source>
        <translation>正在导出到 %1…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 帧</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>%1 × %2 px</source>
        <translation>%1 × %2 像素</translation>
    </message>
    <message>
        <source>vector drawing</source>
        <translation>矢量图</translation>
    </message>
    <message>
        <source>silent</source>
        <translation>无声</translation>
    </message>
    <message>
        <source>with sound</source>
        <translation>有声音</translation>
    </message>
    <message>
        <source>no sound</source>
        <translation>无声音</translation>
    </message>
    <message>
        <source>%1: the export stopped</source>
        <translation>%1：导出已停止</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>已导出到 %1。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>已取消：没有写入任何文件。</translation>
    </message>
    <message>
        <source>Not exported: %1</source>
        <translation>未导出：%1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>WebM video (with transparency)</source>
        <translation>WebM 视频（含透明）</translation>
    </message>
    <message>
        <source>MOV ProRes 4444 (with transparency, for video editors)</source>
        <translation>MOV ProRes 4444（含透明，供视频剪辑软件使用）</translation>
    </message>
    <message>
        <source>Animated PNG</source>
        <translation>动态 PNG</translation>
    </message>
    <message>
        <source>Animated WebP</source>
        <translation>动态 WebP</translation>
    </message>
    <message>
        <source>Telegram sticker (512 px, up to 3 s and 256 KB)</source>
        <translation>Telegram 贴纸（512 像素，最多 3 秒与 256 KB）</translation>
    </message>
    <message>
        <source>Emoji (100 px, up to 3 s and 64 KB)</source>
        <translation>表情符号（100 像素，最多 3 秒与 64 KB）</translation>
    </message>
    <message>
        <source>Slide overlay (1080 px, with sound)</source>
        <translation>幻灯片叠加（1080 像素，含声音）</translation>
    </message>
    <message>
        <source>WebM video (*.webm)</source>
        <translation>WebM 视频 (*.webm)</translation>
    </message>
    <message>
        <source>MOV video (*.mov)</source>
        <translation>MOV 视频 (*.mov)</translation>
    </message>
    <message>
        <source>Animated PNG (*.apng)</source>
        <translation>动态 PNG (*.apng)</translation>
    </message>
    <message>
        <source>Animated WebP (*.webp)</source>
        <translation>动态 WebP (*.webp)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Ready-made settings for a place where talking faces are shared; the export keeps to its limits or says why it cannot</source>
        <translation>为分享说话脸的地方准备好的设置；导出会遵守其限制，或说明为何无法做到</translation>
    </message>
    <message>
        <source>Transparent</source>
        <translation>透明</translation>
    </message>
    <message>
        <source>Colour…</source>
        <translation>颜色…</translation>
    </message>
    <message>
        <source>Photo…</source>
        <translation>照片…</translation>
    </message>
    <message>
        <source>Automatic: transparent for WebM, MOV, APNG, WebP and PNG frames, white for MP4 and GIF</source>
        <translation>自动：WebM、MOV、APNG、WebP 与 PNG 帧为透明，MP4 与 GIF 为白色</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>To the end</source>
        <translation>到结尾</translation>
    </message>
    <message>
        <source>for</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>&amp;Preset:</source>
        <translation>预设(&amp;P)：</translation>
    </message>
    <message>
        <source>&amp;Background:</source>
        <translation>背景(&amp;B)：</translation>
    </message>
    <message>
        <source>Fro&amp;m:</source>
        <translation>从(&amp;M)：</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>颜色：%1</translation>
    </message>
    <message>
        <source>Photo: %1</source>
        <translation>照片：%1</translation>
    </message>
    <message>
        <source>Background Colour</source>
        <translation>背景颜色</translation>
    </message>
    <message>
        <source>Background Photo</source>
        <translation>背景照片</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.webp *.bmp)</source>
        <translation>图像 (*.png *.jpg *.jpeg *.webp *.bmp)</translation>
    </message>
    <message>
        <source>cannot export: %1</source>
        <translation>无法导出：%1</translation>
    </message>
</context>
<context>
    <name>toonface::FrameDecoder</name>
    <message>
        <source>%1: has no frame %2 (it has %3)</source>
        <translation>%1：没有第 %2 帧（只有 %3 帧）</translation>
    </message>
</context>
<context>
    <name>toonface::ImageFile</name>
    <message>
        <source>a WebP image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>这是 WebP 图像，此版本无法读取；请转换为 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a HEIC image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>这是 HEIC 图像，此版本无法读取；请转换为 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>an AVIF image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>这是 AVIF 图像，此版本无法读取；请转换为 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a TIFF image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>这是 TIFF 图像，此版本无法读取；请转换为 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a video or audio file (MP4/QuickTime), not a photo</source>
        <translation>这是视频或音频文件（MP4/QuickTime），不是照片</translation>
    </message>
    <message>
        <source>a WAV audio file, not a photo</source>
        <translation>这是 WAV 音频文件，不是照片</translation>
    </message>
    <message>
        <source>an audio file, not a photo</source>
        <translation>这是音频文件，不是照片</translation>
    </message>
    <message>
        <source>a PDF document, not an image</source>
        <translation>这是 PDF 文档，不是图像</translation>
    </message>
    <message>
        <source>a ZIP archive (or an office document), not an image</source>
        <translation>这是 ZIP 压缩包（或办公文档），不是图像</translation>
    </message>
    <message>
        <source>text, not an image (it starts with &quot;%1&quot;)</source>
        <translation>这是文本，不是图像（开头为“%1”）</translation>
    </message>
    <message>
        <source>not an image (unrecognised data starting with %1)</source>
        <translation>不是图像（无法识别的数据，开头为 %1）</translation>
    </message>
    <message>
        <source>its %1 chunk claims %2 bytes, but only %3 are left in the file</source>
        <translation>其 %1 块声称有 %2 字节，但文件只剩 %3 字节</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <source>is a folder, not an image</source>
        <translation>这是文件夹，不是图像</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>文件是空的</translation>
    </message>
    <message>
        <source>the file is too large for a photo (%1 MB)</source>
        <translation>文件太大，不像是照片（%1 MB）</translation>
    </message>
    <message>
        <source>cannot read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>the JPEG image is truncated (the file ends before the image data does)</source>
        <translation>JPEG 图像不完整（文件在图像数据结束前就结束了）</translation>
    </message>
    <message>
        <source>the PNG image is corrupt or truncated (%1)</source>
        <translation>PNG 图像已损坏或不完整（%1）</translation>
    </message>
    <message>
        <source>the %1 image is empty (%2 × %3 pixels)</source>
        <translation>%1 图像是空的（%2 × %3 像素）</translation>
    </message>
    <message>
        <source>the image is too large: %1 × %2 pixels (%3 megapixels); the limit is %4 megapixels</source>
        <translation>图像太大：%1 × %2 像素（%3 百万像素）；上限为 %4 百万像素</translation>
    </message>
    <message>
        <source>the %1 image is corrupt or truncated (%2)</source>
        <translation>%1 图像已损坏或不完整（%2）</translation>
    </message>
    <message>
        <source>cannot read layer file %1: %2</source>
        <translation>无法读取图层文件 %1：%2</translation>
    </message>
    <message>
        <source>layer file %1 is not a valid SVG file: %2</source>
        <translation>图层文件 %1 不是有效的 SVG 文件：%2</translation>
    </message>
    <message>
        <source>the root element is &lt;%1&gt;, not &lt;svg&gt;</source>
        <translation>根元素是 &lt;%1&gt;，不是 &lt;svg&gt;</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>第 %1 行第 %2 列：%3</translation>
    </message>
    <message>
        <source>no root element</source>
        <translation>没有根元素</translation>
    </message>
    <message>
        <source>elements nested more than %1 deep</source>
        <translation>元素嵌套超过 %1 层</translation>
    </message>
    <message>
        <source>more than %1 elements</source>
        <translation>超过 %1 个元素</translation>
    </message>
    <message>
        <source>the entity &amp;%1; is not defined</source>
        <translation>实体 &amp;%1; 未定义</translation>
    </message>
</context>
<context>
    <name>toonface::ImportVideoDialog</name>
    <message>
        <source>Snap to the nine mouth &amp;shapes (mouth keys)</source>
        <translation>对齐九种口型(&amp;S)（口型关键帧）</translation>
    </message>
    <message>
        <source>Keep the &amp;continuous motion (pose keys)</source>
        <translation>保留连续动作(&amp;C)（姿势关键帧）</translation>
    </message>
    <message>
        <source>At the &amp;playhead (%1)</source>
        <translation>在播放头处（%1）(&amp;P)</translation>
    </message>
    <message>
        <source>At the s&amp;tart (0 s)</source>
        <translation>从开头（0 秒）(&amp;T)</translation>
    </message>
    <message>
        <source>Use the neutral frame as the p&amp;hoto (a new project with its face)</source>
        <translation>使用中性帧作为照片(&amp;H)（以其人脸新建项目）</translation>
    </message>
    <message>
        <source>Import Video</source>
        <translation>导入视频</translation>
    </message>
    <message>
        <source>Tracks a clip of a person speaking: the face of the neutral frame is the rest pose, and the motion of every other frame lands on the timeline as key frames (pose, blinks, gaze, head), editable like any others.</source>
        <translation>跟踪一段人物说话的片段：中性帧的脸是静止姿势，其他每一帧的动作都会以关键帧（姿势、眨眼、视线、头部）放到时间轴上，可像其他关键帧一样编辑。</translation>
    </message>
    <message>
        <source>A video of a face speaking</source>
        <translation>一段人脸说话的视频</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Choose a clip</source>
        <translation>选择片段</translation>
    </message>
    <message>
        <source>The frame whose face is at rest: mouth closed, eyes open, looking ahead</source>
        <translation>人脸处于静止状态的帧：闭嘴、睁眼、直视前方</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Landmarks</source>
        <translation>关键点</translation>
    </message>
    <message>
        <source>Classic (thesis ch. 6)</source>
        <translation>经典（论文第 6 章）</translation>
    </message>
    <message>
        <source>The project has no face yet: the neutral frame becomes its photo, saved as a PNG beside the clip</source>
        <translation>项目还没有人脸：中性帧将成为它的照片，以 PNG 保存在片段旁</translation>
    </message>
    <message>
        <source>&amp;Clip:</source>
        <translation>片段(&amp;C)：</translation>
    </message>
    <message>
        <source>&amp;Neutral frame:</source>
        <translation>中性帧(&amp;N)：</translation>
    </message>
    <message>
        <source>&amp;Method:</source>
        <translation>方法(&amp;M)：</translation>
    </message>
    <message>
        <source>Mouth:</source>
        <translation>口型：</translation>
    </message>
    <message>
        <source>Sound:</source>
        <translation>声音：</translation>
    </message>
    <message>
        <source>Starts:</source>
        <translation>开始于：</translation>
    </message>
    <message>
        <source>Photo:</source>
        <translation>照片：</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>导入(&amp;I)</translation>
    </message>
    <message>
        <source>Tracking frame %1 of %2</source>
        <translation>正在跟踪第 %1 帧，共 %2 帧</translation>
    </message>
    <message>
        <source>Tracking frame %1</source>
        <translation>正在跟踪第 %1 帧</translation>
    </message>
    <message>
        <source>No picture</source>
        <translation>没有画面</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 帧</numerusform>
        </translation>
    </message>
    <message>
        <source>frames not counted</source>
        <translation>未统计帧数</translation>
    </message>
    <message>
        <source>%1 × %2, %3 at %4 fps, %5, %6</source>
        <translation>%1 × %2，%3，%4 fps，%5，%6</translation>
    </message>
    <message>
        <source>with sound</source>
        <translation>有声音</translation>
    </message>
    <message>
        <source>no sound</source>
        <translation>无声音</translation>
    </message>
    <message>
        <source>Decoding…</source>
        <translation>正在解码…</translation>
    </message>
    <message>
        <source>Video (*.mp4 *.mov *.mkv *.webm *.avi *.mpg *.mpeg *.m4v *.gif);;All files (*)</source>
        <translation>视频 (*.mp4 *.mov *.mkv *.webm *.avi *.mpg *.mpeg *.m4v *.gif);;所有文件 (*)</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>第 %1 帧</translation>
    </message>
    <message>
        <source>Finding the face on frame %1</source>
        <translation>正在第 %1 帧上查找人脸</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Nothing was changed.</source>
        <translation>没有任何更改。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was changed.</source>
        <translation>已取消：没有任何更改。</translation>
    </message>
    <message>
        <source>%1: no frame could be tracked</source>
        <translation>%1：没有任何帧可以跟踪</translation>
    </message>
    <message>
        <source>%1: cannot write the neutral frame there</source>
        <translation>%1：无法在该处写入中性帧</translation>
    </message>
    <message>
        <source>Import Video %1</source>
        <translation>导入视频 %1</translation>
    </message>
    <message>
        <source>Use the clip&apos;s s&amp;ound (a new clip on the audio track)</source>
        <translation>使用片段的声音（音轨上的新片段）(&amp;O)</translation>
    </message>
    <message>
        <source>It plays over %1: &amp;replace it (else both sound together)</source>
        <translation>会与 %1 重叠播放：替换它（否则两者一起发声）(&amp;R)</translation>
    </message>
    <message>
        <source>Looking for a frame at rest in the first seconds…</source>
        <translation>正在开头几秒中寻找静止的一帧…</translation>
    </message>
    <message>
        <source>No face was found in the first seconds: choose a frame that shows one.</source>
        <translation>开头几秒中找不到脸：请选一帧有脸的画面。</translation>
    </message>
    <message>
        <source>mouth closed, eyes open, in a silence</source>
        <translation>嘴闭着、眼睁开、无人说话</translation>
    </message>
    <message>
        <source>mouth closed, eyes open</source>
        <translation>嘴闭着、眼睁开</translation>
    </message>
    <message>
        <source>Frame %1 looks at rest (%2); your choice is kept.</source>
        <translation>第 %1 帧看来是静止的（%2）；保留您的选择。</translation>
    </message>
    <message>
        <source>Frame %1 was chosen: %2. Pick another if it is not at rest.</source>
        <translation>已选第 %1 帧：%2。若不是静止的，请另选一帧。</translation>
    </message>
    <message>
        <source>Off: the project has a sound already (%1). Tick to add the clip&apos;s as well.</source>
        <translation>未勾选：项目已有声音（%1）。勾选即可一并加入片段的声音。</translation>
    </message>
</context>
<context>
    <name>toonface::LanguageBox</name>
    <message>
        <source>Detect from the script</source>
        <translation>根据文稿自动判断</translation>
    </message>
    <message>
        <source>Mandarin (普通话)</source>
        <translation>普通话</translation>
    </message>
    <message>
        <source>English</source>
        <translation>英语</translation>
    </message>
</context>
<context>
    <name>toonface::LayersEditor</name>
    <message>
        <source>Your own SVG drawings over or under the face, in drawing order; untick to hide</source>
        <translation>你自己的 SVG 图画，画在脸的前面或后面，按绘制顺序排列；取消勾选即隐藏</translation>
    </message>
    <message>
        <source>Add…</source>
        <translation>添加…</translation>
    </message>
    <message>
        <source>Add a drawing from an SVG file (clothing, an accessory); the project keeps a copy</source>
        <translation>从 SVG 文件添加图画（衣服、配饰）；项目会保存一份副本</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <source>Draw earlier (further back)</source>
        <translation>较早绘制（更靠后）</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <source>Draw later (further forward)</source>
        <translation>较晚绘制（更靠前）</translation>
    </message>
    <message>
        <source>Across from the face&apos;s centre, in eye distances (right is positive)</source>
        <translation>从脸部中心水平偏移，以双眼距离为单位（向右为正）</translation>
    </message>
    <message>
        <source>Down from the face&apos;s centre, in eye distances</source>
        <translation>从脸部中心向下偏移，以双眼距离为单位</translation>
    </message>
    <message>
        <source>The drawing&apos;s width, in eye distances</source>
        <translation>图画的宽度，以双眼距离为单位</translation>
    </message>
    <message>
        <source>In front of the face</source>
        <translation>在脸的前面</translation>
    </message>
    <message>
        <source>Unticked, the drawing lies behind the head, over the neck and shoulders</source>
        <translation>取消勾选时，图画位于头部后面、脖子和肩膀之上</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>宽度：</translation>
    </message>
    <message>
        <source>Remove layer</source>
        <translation>移除图层</translation>
    </message>
    <message>
        <source>Show layer</source>
        <translation>显示图层</translation>
    </message>
    <message>
        <source>Hide layer</source>
        <translation>隐藏图层</translation>
    </message>
    <message>
        <source>Move layer</source>
        <translation>移动图层</translation>
    </message>
    <message>
        <source>Resize layer</source>
        <translation>调整图层大小</translation>
    </message>
    <message>
        <source>Layer in front</source>
        <translation>图层移到前面</translation>
    </message>
    <message>
        <source>Layer behind</source>
        <translation>图层移到后面</translation>
    </message>
    <message>
        <source>There is no face to place %1 on.</source>
        <translation>没有可以放置 %1 的脸。</translation>
    </message>
    <message>
        <source>Add layer %1</source>
        <translation>添加图层 %1</translation>
    </message>
    <message>
        <source>Add layers</source>
        <translation>添加图层</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg);;All files (*)</source>
        <translation>SVG 图画 (*.svg);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Add layer</source>
        <translation>添加图层</translation>
    </message>
    <message>
        <source>Reorder layers</source>
        <translation>重新排列图层</translation>
    </message>
    <message>
        <source>%1 (behind)</source>
        <translation>%1（后面）</translation>
    </message>
    <message>
        <source>Moves with the head</source>
        <translation>随头部移动</translation>
    </message>
    <message>
        <source>Ticked, the drawing moves, turns and nods with the head (a hat, glasses, earrings); unticked, it stays still as the head moves (clothes)</source>
        <translation>勾选时，图画随头部移动、转动和点头（帽子、眼镜、耳环）；不勾选时，头部移动时它保持不动（衣服）</translation>
    </message>
    <message>
        <source>Layer follows the head</source>
        <translation>图层随头部移动</translation>
    </message>
    <message>
        <source>Layer stays still</source>
        <translation>图层保持不动</translation>
    </message>
</context>
<context>
    <name>toonface::LipSyncDialog</name>
    <message>
        <source>Lip Sync</source>
        <translation>口型同步</translation>
    </message>
    <message>
        <source>Lip Sync from Recording</source>
        <translation>根据录音做口型同步</translation>
    </message>
    <message>
        <source>An audio file, or a video whose sound is used</source>
        <translation>音频文件，或使用其声音的视频</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Where the recording starts on the timeline</source>
        <translation>录音在时间轴上的开始位置</translation>
    </message>
    <message>
        <source>Type the words spoken in the recording (Chinese characters, pinyin, Zhuyin or English), or open a text file.</source>
        <translation>输入录音中说的话（汉字、拼音、注音或英文），或打开文本文件。</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <source>&amp;Recording:</source>
        <translation>录音(&amp;R)：</translation>
    </message>
    <message>
        <source>&amp;Starts at:</source>
        <translation>开始于(&amp;S)：</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <source>S&amp;cript:</source>
        <translation>文稿(&amp;C)：</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1：无法读取（%2）</translation>
    </message>
    <message>
        <source>%1: not a UTF-8 text file</source>
        <translation>%1：不是 UTF-8 文本文件</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>录音</translation>
    </message>
    <message>
        <source>Sound and video (*.wav *.flac *.mp3 *.ogg *.opus *.m4a *.aac *.mp4 *.mov *.mkv *.webm *.avi);;All files (*)</source>
        <translation>声音和视频 (*.wav *.flac *.mp3 *.ogg *.opus *.m4a *.aac *.mp4 *.mov *.mkv *.webm *.avi);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>文稿</translation>
    </message>
    <message>
        <source>Text (*.txt);;All files (*)</source>
        <translation>文本 (*.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Type or open the script the recording speaks.</source>
        <translation>输入或打开录音所朗读的文稿。</translation>
    </message>
    <message>
        <source>Loading the character dictionary…</source>
        <translation>正在加载字典…</translation>
    </message>
    <message numerus="yes">
        <source>%n word(s) in English</source>
        <translation>
            <numerusform>%n 个英文单词</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n syllable(s) in Mandarin</source>
        <translation>
            <numerusform>%n 个普通话音节</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading %1</source>
        <translation>正在读取 %1</translation>
    </message>
    <message>
        <source>the script</source>
        <translation>文稿</translation>
    </message>
    <message>
        <source>Lip Sync from %1</source>
        <translation>根据 %1 做口型同步</translation>
    </message>
    <message>
        <source>Aligns a recording with the script it speaks, syllable by syllable. The recording becomes a clip on the audio track; the mouth keys and syllables where it plays are replaced, the other recordings and the rest of the timeline are kept.</source>
        <translation>逐音节将录音与其文稿对齐。录音成为音轨上的一个片段；其播放范围内的口型关键帧与音节会被替换，其他录音与时间轴的其余部分都会保留。</translation>
    </message>
</context>
<context>
    <name>toonface::LipSyncFile</name>
    <message>
        <source>unexpected end of file, expected %1</source>
        <translation>文件意外结束，应有%1</translation>
    </message>
    <message>
        <source>expected %1 (an integer of at least %2), found &apos;%3&apos;</source>
        <translation>应为%1（至少为 %2 的整数），实际为“%3”</translation>
    </message>
    <message>
        <source>%1: line %2: %3</source>
        <translation>%1：第 %2 行：%3</translation>
    </message>
    <message>
        <source>unknown mouth shape &apos;%1&apos; (known: %2)</source>
        <translation>未知的口型“%1”（已知：%2）</translation>
    </message>
    <message>
        <source>expected &apos;start&lt;TAB&gt;shape&apos;, found &apos;%1&apos;</source>
        <translation>应为“开始时间&lt;TAB&gt;口型”，实际为“%1”</translation>
    </message>
    <message>
        <source>expected a start time in seconds (a number of at least 0), found &apos;%1&apos;</source>
        <translation>应为以秒计的开始时间（至少为 0 的数字），实际为“%1”</translation>
    </message>
    <message>
        <source>time %1 is before the previous line&apos;s %2</source>
        <translation>时间 %1 早于上一行的 %2</translation>
    </message>
    <message>
        <source>%1: line %2: not valid JSON: %3</source>
        <translation>%1：第 %2 行：不是有效的 JSON：%3</translation>
    </message>
    <message>
        <source>expected a JSON object with mouthCues</source>
        <translation>应为含有 mouthCues 的 JSON 对象</translation>
    </message>
    <message>
        <source>%1: expected a duration of at least 0</source>
        <translation>%1：应为至少 0 的时长</translation>
    </message>
    <message>
        <source>%1: expected a time of at least 0</source>
        <translation>%1：应为至少 0 的时间</translation>
    </message>
    <message>
        <source>%1: ends (%2) before it starts (%3)</source>
        <translation>%1：结束时间（%2）早于开始时间（%3）</translation>
    </message>
    <message>
        <source>%1: starts (%2) before the previous cue ends (%3)</source>
        <translation>%1：开始时间（%2）早于上一个提示的结束时间（%3）</translation>
    </message>
    <message>
        <source>%1: unknown mouth shape &apos;%2&apos; (known: %3)</source>
        <translation>%1：未知的口型“%2”（已知：%3）</translation>
    </message>
    <message>
        <source>the header &apos;lipsync version 1&apos;</source>
        <translation>文件头“lipsync version 1”</translation>
    </message>
    <message>
        <source>expected the header &apos;lipsync version 1&apos;, found &apos;%1&apos;</source>
        <translation>应为文件头“lipsync version 1”，实际为“%1”</translation>
    </message>
    <message>
        <source>the sound file</source>
        <translation>声音文件</translation>
    </message>
    <message>
        <source>the frame rate</source>
        <translation>帧率</translation>
    </message>
    <message>
        <source>the duration in frames</source>
        <translation>以帧计的时长</translation>
    </message>
    <message>
        <source>the number of voices</source>
        <translation>声部数量</translation>
    </message>
    <message>
        <source>the voice&apos;s name</source>
        <translation>声部名称</translation>
    </message>
    <message>
        <source>the voice&apos;s text</source>
        <translation>声部文本</translation>
    </message>
    <message>
        <source>the number of phrases</source>
        <translation>短语数量</translation>
    </message>
    <message>
        <source>the text of phrase %1</source>
        <translation>第 %1 个短语的文本</translation>
    </message>
    <message>
        <source>the start frame of phrase %1</source>
        <translation>第 %1 个短语的开始帧</translation>
    </message>
    <message>
        <source>the end frame of phrase %1</source>
        <translation>第 %1 个短语的结束帧</translation>
    </message>
    <message>
        <source>the number of words of phrase %1</source>
        <translation>第 %1 个短语的词数</translation>
    </message>
    <message>
        <source>word %1 of phrase %2 (&apos;text start end phonemes&apos;)</source>
        <translation>第 %2 个短语的第 %1 个词（“文本 开始 结束 音素数”）</translation>
    </message>
    <message>
        <source>expected %1, found &apos;%2&apos;</source>
        <translation>应为%1，实际为“%2”</translation>
    </message>
    <message>
        <source>the start frame of &apos;%1&apos;</source>
        <translation>“%1”的开始帧</translation>
    </message>
    <message>
        <source>the end frame of &apos;%1&apos;</source>
        <translation>“%1”的结束帧</translation>
    </message>
    <message>
        <source>the phoneme count of &apos;%1&apos;</source>
        <translation>“%1”的音素数</translation>
    </message>
    <message>
        <source>word &apos;%1&apos; ends (frame %2) before it starts (frame %3)</source>
        <translation>词“%1”的结束（第 %2 帧）早于开始（第 %3 帧）</translation>
    </message>
    <message>
        <source>phoneme %1 of &apos;%2&apos; (&apos;frame name&apos;)</source>
        <translation>“%2”的第 %1 个音素（“帧 名称”）</translation>
    </message>
    <message>
        <source>the frame of a phoneme</source>
        <translation>音素的帧</translation>
    </message>
    <message>
        <source>phoneme frame %1 is before the previous phoneme&apos;s %2</source>
        <translation>音素帧 %1 早于上一个音素的 %2</translation>
    </message>
    <message>
        <source>the header &apos;MohoSwitch1&apos;</source>
        <translation>文件头“MohoSwitch1”</translation>
    </message>
    <message>
        <source>expected the header &apos;MohoSwitch1&apos;, found &apos;%1&apos;</source>
        <translation>应为文件头“MohoSwitch1”，实际为“%1”</translation>
    </message>
    <message>
        <source>expected &apos;frame shape&apos;, found &apos;%1&apos;</source>
        <translation>应为“帧 口型”，实际为“%1”</translation>
    </message>
    <message>
        <source>a frame number</source>
        <translation>帧编号</translation>
    </message>
    <message>
        <source>frame %1 is before the previous line&apos;s frame %2</source>
        <translation>第 %1 帧早于上一行的第 %2 帧</translation>
    </message>
    <message>
        <source>%1: cannot read at %2 frames per second</source>
        <translation>%1：无法以每秒 %2 帧读取</translation>
    </message>
    <message>
        <source>%1: not saved: %2</source>
        <translation>%1：未保存：%2</translation>
    </message>
    <message>
        <source>%1: unknown lip-sync format (expected .tsv, .json, .pgo or .dat)</source>
        <translation>%1：未知的口型同步格式（应为 .tsv、.json、.pgo 或 .dat）</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>no interval tier named &apos;%1&apos;</source>
        <translation>没有名为“%1”的区间层</translation>
    </message>
</context>
<context>
    <name>toonface::LiveSession</name>
    <message>
        <source>Rest pose set (tracking by %1)</source>
        <translation>已设置静止姿势（以 %1 跟踪）</translation>
    </message>
    <message>
        <source>No face for the rest pose: %1</source>
        <translation>没有可作为静止姿势的人脸：%1</translation>
    </message>
</context>
<context>
    <name>toonface::LiveTakeText</name>
    <message>
        <source>Nothing was recorded: no frame with a face was tracked.</source>
        <translation>没有录到任何内容：没有跟踪到任何有人脸的帧。</translation>
    </message>
    <message>
        <source>%1: cannot create its folder</source>
        <translation>%1：无法创建其文件夹</translation>
    </message>
    <message>
        <source>Record Live Take</source>
        <translation>录制实时表演</translation>
    </message>
    <message>
        <source>Recorded %1 s (%2 frames) with its sound, saved as %3</source>
        <translation>已录制 %1 秒（%2 帧）并含声音，保存为 %3</translation>
    </message>
    <message>
        <source>Recorded %1 s (%2 frames): motion only, no sound</source>
        <translation>已录制 %1 秒（%2 帧）：只有动作，没有声音</translation>
    </message>
    <message>
        <source>Nothing was recorded: the microphone heard nothing.</source>
        <translation>没有录到任何内容：麦克风什么也没听到。</translation>
    </message>
    <message>
        <source>Recorded %1 s of the microphone: the mouth, with its sound saved as %2</source>
        <translation>已录制麦克风 %1 秒：嘴巴动作，声音保存为 %2</translation>
    </message>
    <message>
        <source>Recorded %1 s of the microphone: the mouth, no sound</source>
        <translation>已录制麦克风 %1 秒：嘴巴动作，没有声音</translation>
    </message>
</context>
<context>
    <name>toonface::LiveWindow</name>
    <message>
        <source>&amp;Loop clip</source>
        <translation>循环播放片段(&amp;L)</translation>
    </message>
    <message>
        <source>Set &amp;Rest Pose</source>
        <translation>设置静止姿势(&amp;R)</translation>
    </message>
    <message>
        <source>● &amp;Record</source>
        <translation>● 录制(&amp;R)</translation>
    </message>
    <message>
        <source>Live Mode — Toonface</source>
        <translation>实时模式 — Toonface</translation>
    </message>
    <message>
        <source>Mouth from microphone</source>
        <translation>嘴巴跟随麦克风</translation>
    </message>
    <message>
        <source>Take the current frame as the performer&apos;s neutral face</source>
        <translation>将当前帧作为表演者的中性脸</translation>
    </message>
    <message>
        <source>Record the performance onto the timeline at the playhead</source>
        <translation>将表演录制到时间轴的播放头处</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>来源：</translation>
    </message>
    <message>
        <source>&lt;b&gt;Performer&lt;/b&gt;</source>
        <translation>&lt;b&gt;表演者&lt;/b&gt;</translation>
    </message>
    <message>
        <source>The next frame becomes the rest pose…</source>
        <translation>下一帧将成为静止姿势…</translation>
    </message>
    <message>
        <source>Open a photo with a face first: the cartoon of that face follows the performer.</source>
        <translation>请先打开一张有人脸的照片：那张脸的卡通会跟着表演者动。</translation>
    </message>
    <message>
        <source>No camera</source>
        <translation>没有摄像头</translation>
    </message>
    <message>
        <source>Camera: %1</source>
        <translation>摄像头：%1</translation>
    </message>
    <message>
        <source>Video file…</source>
        <translation>视频文件…</translation>
    </message>
    <message>
        <source>Perform from a Video</source>
        <translation>从视频表演</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.mov *.mkv *.avi *.mpg *.mpeg *.webm);;All files (*)</source>
        <translation>视频 (*.mp4 *.mov *.mkv *.avi *.mpg *.mpeg *.webm);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Camera “%1”: look straight at it with a relaxed face</source>
        <translation>摄像头“%1”：请放松面部并直视镜头</translation>
    </message>
    <message>
        <source>Video file: %1</source>
        <translation>视频文件：%1</translation>
    </message>
    <message>
        <source>Playing %1 as the performer</source>
        <translation>正在播放 %1 作为表演者</translation>
    </message>
    <message>
        <source>The clip has no sound: the mouth follows the camera.</source>
        <translation>片段没有声音：嘴巴跟随摄像头。</translation>
    </message>
    <message>
        <source>The mouth follows the camera.</source>
        <translation>嘴巴跟随摄像头。</translation>
    </message>
    <message>
        <source>■ &amp;Stop</source>
        <translation>■ 停止(&amp;S)</translation>
    </message>
    <message>
        <source>Recording: motion only (no microphone)</source>
        <translation>录制中：只有动作（没有麦克风）</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>录制中…</translation>
    </message>
    <message>
        <source>No frames yet.</source>
        <translation>还没有帧。</translation>
    </message>
    <message>
        <source>Frames shown: %1 of %2
Latency to the picture: %3 ms (95 %: %4 ms)
Face lost in %5 frames%6</source>
        <translation>已显示帧：%1 / %2
到画面的延迟：%3 毫秒（95 %：%4 毫秒）
跟丢人脸的帧：%5 帧%6</translation>
    </message>
    <message>
        <source>
● Recording</source>
        <translation>
● 录制中</translation>
    </message>
    <message>
        <source>Choose “Video file…” to perform from a clip, or “Microphone only” to speak for the cartoon.</source>
        <translation>选择“视频文件…”用视频片段表演，或选择“仅麦克风”为卡通人物说话。</translation>
    </message>
    <message>
        <source>Choose a camera, a video file, or the microphone only.</source>
        <translation>请选择摄像头、视频文件或仅麦克风。</translation>
    </message>
    <message>
        <source>Microphone only (no camera)</source>
        <translation>仅麦克风（不用摄像头）</translation>
    </message>
    <message>
        <source>Microphone “%1”</source>
        <translation>麦克风“%1”</translation>
    </message>
    <message>
        <source>Listening to “%1”: speak, and the cartoon speaks with you</source>
        <translation>正在收听“%1”：说话时，卡通人物会跟着你说</translation>
    </message>
    <message>
        <source>Start a camera, a clip or the microphone, with a face open, before recording.</source>
        <translation>录制前请先打开一张有人脸的照片，并启动摄像头、视频片段或麦克风。</translation>
    </message>
    <message>
        <source>Mouth from the lips in the picture</source>
        <translation>嘴巴跟随画面中的嘴唇</translation>
    </message>
    <message>
        <source>Lips in the picture, microphone when they are lost</source>
        <translation>画面中的嘴唇，跟丢时用麦克风</translation>
    </message>
    <message>
        <source>What drives the cartoon&apos;s mouth: the lips the source shows, the loudness and colour of the voice, or both</source>
        <translation>驱动卡通嘴巴的来源：画面中的嘴唇、声音的大小与音色，或两者并用</translation>
    </message>
</context>
<context>
    <name>toonface::MainWindow</name>
    <message>
        <source>%1%</source>
        <translation>%1%</translation>
    </message>
    <message>
        <source>Detecting the face: %1</source>
        <translation>正在检测人脸：%1</translation>
    </message>
    <message>
        <source>Landmark model unavailable (%1): detection may fail, but points can be placed by hand.</source>
        <translation>关键点模型不可用（%1）：检测可能失败，但仍可手动放置特征点。</translation>
    </message>
    <message>
        <source>&amp;Open Photo or Project…</source>
        <translation>打开照片或项目(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Export Cartoon…</source>
        <translation>导出卡通(&amp;E)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Re-&amp;detect Points</source>
        <translation>重新检测特征点(&amp;D)</translation>
    </message>
    <message>
        <source>Detect the face again and replace every point</source>
        <translation>重新检测人脸并替换所有特征点</translation>
    </message>
    <message>
        <source>Re-detect &amp;Keeping My Points</source>
        <translation>重新检测并保留我的特征点(&amp;K)</translation>
    </message>
    <message>
        <source>Detect the face again but keep the points placed by hand</source>
        <translation>重新检测人脸，但保留手动放置的特征点</translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation>自动(&amp;A)</translation>
    </message>
    <message>
        <source>The landmark model where it is installed, the thesis pipeline where it is not</source>
        <translation>已安装关键点模型时使用它，未安装时使用论文流程</translation>
    </message>
    <message>
        <source>&amp;Thesis Pipeline (Classic)</source>
        <translation>论文流程（经典）(&amp;T)</translation>
    </message>
    <message>
        <source>The thesis&apos; steps only: thresholds, eye pair, edges and feature regions; best on a plain background with frontal light</source>
        <translation>只用论文的步骤：阈值、双眼配对、边缘与五官区域；最适合纯色背景和正面光线</translation>
    </message>
    <message>
        <source>&amp;Landmarks</source>
        <translation>关键点(&amp;L)</translation>
    </message>
    <message>
        <source>The landmark model&apos;s 68 points mapped to the face model, hair and ears found around them</source>
        <translation>关键点模型的 68 个点映射到人脸模型，并在其周围找出头发和耳朵</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>缩小(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Actual Size</source>
        <translation>实际大小(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>适应窗口大小(&amp;F)</translation>
    </message>
    <message>
        <source>Zoom to F&amp;ace</source>
        <translation>缩放到人脸(&amp;A)</translation>
    </message>
    <message>
        <source>Show Point &amp;IDs</source>
        <translation>显示特征点编号(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;About Toonface</source>
        <translation>关于 Toonface(&amp;A)</translation>
    </message>
    <message>
        <source>About Toonface</source>
        <translation>关于 Toonface</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Toonface %1&lt;/h3&gt;&lt;p&gt;Personal talking cartoon faces from photos, drawn in SVG.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Toonface %1&lt;/h3&gt;&lt;p&gt;用照片制作会说话的个人卡通脸，以 SVG 绘制。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开的文件(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>Detection &amp;Method</source>
        <translation>检测方法(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Style:</source>
        <translation>风格：</translation>
    </message>
    <message>
        <source>Drawing style of the cartoon</source>
        <translation>卡通的绘制风格</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Photos and projects (*.toonface %1);;Toonface projects (*.toonface);;Photos (%1);;All files (*)</source>
        <translation>照片和项目 (*.toonface %1);;Toonface 项目 (*.toonface);;照片 (%1);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open Photo or Project</source>
        <translation>打开照片或项目</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <source>Cannot Open</source>
        <translation>无法打开</translation>
    </message>
    <message>
        <source>Restored unsaved work on %1.</source>
        <translation>已恢复 %1 未保存的工作。</translation>
    </message>
    <message>
        <source>Photo Missing</source>
        <translation>照片丢失</translation>
    </message>
    <message>
        <source>The project opened, but its photo could not be read:
%1</source>
        <translation>项目已打开，但无法读取它的照片：
%1</translation>
    </message>
    <message>
        <source>Detecting the face…</source>
        <translation>正在检测人脸…</translation>
    </message>
    <message>
        <source>Detection Failed</source>
        <translation>检测失败</translation>
    </message>
    <message>
        <source>%1
The points are unchanged.</source>
        <translation>%1
特征点保持不变。</translation>
    </message>
    <message>
        <source>Detection cancelled.</source>
        <translation>已取消检测。</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Stop detecting the face</source>
        <translation>停止检测人脸</translation>
    </message>
    <message>
        <source>Stop opening the file</source>
        <translation>停止打开文件</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <source>Toonface projects (*.toonface)</source>
        <translation>Toonface 项目 (*.toonface)</translation>
    </message>
    <message>
        <source>Cannot Save</source>
        <translation>无法保存</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已保存 %1。</translation>
    </message>
    <message>
        <source>Export Cartoon</source>
        <translation>导出卡通</translation>
    </message>
    <message>
        <source>SVG image (*.svg);;PNG image (*.png)</source>
        <translation>SVG 图像 (*.svg);;PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Exported %1.</source>
        <translation>已导出 %1。</translation>
    </message>
    <message>
        <source>Cannot Export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>清除菜单(&amp;C)</translation>
    </message>
    <message>
        <source>%1[*] — Toonface</source>
        <translation>%1[*] — Toonface</translation>
    </message>
    <message>
        <source>The detection&apos;s steps appear when it ends</source>
        <translation>检测结束后会显示其步骤</translation>
    </message>
    <message>
        <source>Open a photo: its face detection&apos;s steps can be shown here</source>
        <translation>打开照片：这里可以显示其人脸检测的步骤</translation>
    </message>
    <message>
        <source>No detection steps for this photo: they are not saved in projects. Use Edit ▸ Re-detect Points to see them</source>
        <translation>这张照片没有检测步骤：项目不会保存它们。请使用“编辑 ▸ 重新检测特征点”来查看</translation>
    </message>
    <message>
        <source>Style “%1”</source>
        <translation>风格“%1”</translation>
    </message>
    <message>
        <source> · control point</source>
        <translation> · 控制点</translation>
    </message>
    <message>
        <source> · placed by hand</source>
        <translation> · 手动放置</translation>
    </message>
    <message>
        <source>The cartoon made from %1 is not saved as a project yet. Save it?</source>
        <translation>由 %1 制作的卡通尚未保存为项目。要保存吗？</translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes. Save them?</source>
        <translation>项目 %1 有未保存的更改。要保存吗？</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>%1 at %2, %3</source>
        <translation>%1 位于 %2, %3</translation>
    </message>
    <message>
        <source>User &amp;Manual</source>
        <translation>用户手册(&amp;M)</translation>
    </message>
</context>
<context>
    <name>toonface::ManualDialog</name>
    <message>
        <source>User Manual</source>
        <translation>用户手册</translation>
    </message>
</context>
<context>
    <name>toonface::Media</name>
    <message>
        <source>the data is invalid or damaged</source>
        <translation>数据无效或已损坏</translation>
    </message>
    <message>
        <source>the file ends early</source>
        <translation>文件提前结束</translation>
    </message>
    <message>
        <source>no decoder for it</source>
        <translation>没有对应的解码器</translation>
    </message>
    <message>
        <source>no encoder for it</source>
        <translation>没有对应的编码器</translation>
    </message>
    <message>
        <source>its format is not recognised</source>
        <translation>无法识别其格式</translation>
    </message>
    <message>
        <source>the format cannot be written</source>
        <translation>无法写入此格式</translation>
    </message>
    <message>
        <source>no such file or folder</source>
        <translation>文件或文件夹不存在</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>权限不足</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>这是文件夹</translation>
    </message>
    <message>
        <source>the disk is full</source>
        <translation>磁盘已满</translation>
    </message>
    <message>
        <source>the disk is read-only</source>
        <translation>磁盘为只读</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>内存不足</translation>
    </message>
</context>
<context>
    <name>toonface::MediaAudioTrack</name>
    <message>
        <source>Cannot play the audio file %1: %2</source>
        <translation>无法播放音频文件 %1：%2</translation>
    </message>
    <message>
        <source>The audio file %1 %2.</source>
        <translation>音频文件 %1 %2。</translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <source>is missing</source>
        <translation>丢失</translation>
    </message>
</context>
<context>
    <name>toonface::Microphone</name>
    <message>
        <source>No microphone was found: the sound cannot drive the mouth, and recordings keep the motion only.</source>
        <translation>找不到麦克风：声音无法驱动嘴巴，录制时只保留动作。</translation>
    </message>
    <message>
        <source>The microphone “%1” cannot be opened.</source>
        <translation>无法打开麦克风“%1”。</translation>
    </message>
    <message>
        <source>The microphone “%1” stopped.</source>
        <translation>麦克风“%1”已停止。</translation>
    </message>
</context>
<context>
    <name>toonface::MouthShapesDialog</name>
    <message>
        <source>lips shut (b p m, rest)</source>
        <translation>双唇闭合（b p m、静止）</translation>
    </message>
    <message>
        <source>lower lip under the upper (f)</source>
        <translation>下唇在上齿下（f）</translation>
    </message>
    <message>
        <source>open (most initials, ng, er)</source>
        <translation>张开（多数声母、ng、er）</translation>
    </message>
    <message>
        <source>wide open (a)</source>
        <translation>大张（a）</translation>
    </message>
    <message>
        <source>spread (i, y)</source>
        <translation>展唇（i、y）</translation>
    </message>
    <message>
        <source>rounded (u, w)</source>
        <translation>圆唇（u、w）</translation>
    </message>
    <message>
        <source>half open, spread (e)</source>
        <translation>半开展唇（e）</translation>
    </message>
    <message>
        <source>round open (o)</source>
        <translation>圆唇张开（o）</translation>
    </message>
    <message>
        <source>tongue up (n)</source>
        <translation>舌尖上抬（n）</translation>
    </message>
    <message>
        <source>Corners at the height &amp;midway between the lips (as o)</source>
        <translation>嘴角位于双唇中间的高度(&amp;M)（如 o）</translation>
    </message>
    <message>
        <source>Corners stay where the shape &amp;before put them (as n)</source>
        <translation>嘴角停在前一个口型的位置(&amp;B)（如 n）</translation>
    </message>
    <message>
        <source>&amp;Reset Shape</source>
        <translation>重置口型(&amp;R)</translation>
    </message>
    <message>
        <source>Mouth Shapes</source>
        <translation>口型</translation>
    </message>
    <message>
        <source>Drag a point to move it</source>
        <translation>拖动特征点来移动它</translation>
    </message>
    <message>
        <source>How the four mouth control points move</source>
        <translation>四个嘴部控制点如何移动</translation>
    </message>
    <message>
        <source>On this face MNS0 (nose to mouth) = %1 px, MW0 (mouth width) = %2 px, LowerLipH = %3 px, ES0/100 = %4 px. y grows downwards.</source>
        <translation>在这张脸上 MNS0（鼻到嘴）= %1 像素，MW0（嘴宽）= %2 像素，LowerLipH = %3 像素，ES0/100 = %4 像素。y 向下增大。</translation>
    </message>
    <message>
        <source>Reset &amp;All</source>
        <translation>全部重置(&amp;A)</translation>
    </message>
    <message>
        <source>= pixels here</source>
        <translation>= 此处的像素</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>%1 px</source>
        <translation>%1 像素</translation>
    </message>
    <message>
        <source>%1 — %2%3</source>
        <translation>%1 — %2%3</translation>
    </message>
    <message>
        <source> (edited)</source>
        <translation> （已编辑）</translation>
    </message>
    <message>
        <source> •</source>
        <translation> •</translation>
    </message>
    <message>
        <source>Edit Mouth Shapes</source>
        <translation>编辑口型</translation>
    </message>
    <message>
        <source>Upper lip</source>
        <translation>上唇</translation>
    </message>
    <message>
        <source>Lower lip</source>
        <translation>下唇</translation>
    </message>
    <message>
        <source>Left corner</source>
        <translation>左嘴角</translation>
    </message>
    <message>
        <source>Right corner</source>
        <translation>右嘴角</translation>
    </message>
    <message>
        <source>Drag the four points of the mouth in the picture to change the shape. Each shape fits every face: it moves the lips in proportion to this face&apos;s mouth.</source>
        <translation>在图中拖动嘴巴的四个点即可改变口型。每个口型适用于任何脸：它按这张脸的嘴巴比例移动嘴唇。</translation>
    </message>
    <message>
        <source>Ad&amp;vanced: the numbers</source>
        <translation>高级：数值(&amp;V)</translation>
    </message>
    <message>
        <source>× nose to mouth</source>
        <translation>× 鼻到嘴</translation>
    </message>
    <message>
        <source>× mouth width</source>
        <translation>× 嘴宽</translation>
    </message>
    <message>
        <source>× lower lip</source>
        <translation>× 下唇</translation>
    </message>
    <message>
        <source>× eye distance/100</source>
        <translation>× 眼距/100</translation>
    </message>
    <message>
        <source>MNS0: the height from the tip of the nose to the lips</source>
        <translation>MNS0：鼻尖到嘴唇的高度</translation>
    </message>
    <message>
        <source>MW0: the width of the mouth, corner to corner</source>
        <translation>MW0：嘴巴的宽度，从嘴角到嘴角</translation>
    </message>
    <message>
        <source>LowerLipH: the height of the lower lip</source>
        <translation>LowerLipH：下唇的高度</translation>
    </message>
    <message>
        <source>ES0/100: a hundredth of the distance between the eyes</source>
        <translation>ES0/100：两眼距离的百分之一</translation>
    </message>
    <message>
        <source>The move on this face, in pixels</source>
        <translation>在这张脸上移动的像素</translation>
    </message>
</context>
<context>
    <name>toonface::Names</name>
    <message>
        <source>Neutral</source>
        <translation>中性</translation>
    </message>
    <message>
        <source>Smile</source>
        <translation>微笑</translation>
    </message>
    <message>
        <source>Sad</source>
        <translation>悲伤</translation>
    </message>
    <message>
        <source>Angry</source>
        <translation>生气</translation>
    </message>
    <message>
        <source>Surprise</source>
        <translation>惊讶</translation>
    </message>
    <message>
        <source>Normal</source>
        <comment>drawing style</comment>
        <translation>普通</translation>
    </message>
    <message>
        <source>Soft</source>
        <comment>drawing style</comment>
        <translation>柔和</translation>
    </message>
    <message>
        <source>Bold</source>
        <comment>drawing style</comment>
        <translation>粗犷</translation>
    </message>
    <message>
        <source>Cute</source>
        <comment>drawing style</comment>
        <translation>可爱</translation>
    </message>
    <message>
        <source>Angular</source>
        <comment>eyebrow variant</comment>
        <translation>棱角</translation>
    </message>
    <message>
        <source>Curved</source>
        <comment>eyebrow variant</comment>
        <translation>弧形</translation>
    </message>
    <message>
        <source>Thick</source>
        <comment>eyebrow variant</comment>
        <translation>粗眉</translation>
    </message>
    <message>
        <source>Full</source>
        <comment>nose variant</comment>
        <translation>完整</translation>
    </message>
    <message>
        <source>Simple</source>
        <comment>nose variant</comment>
        <translation>简约</translation>
    </message>
    <message>
        <source>Tip only</source>
        <comment>nose variant</comment>
        <translation>只画鼻头</translation>
    </message>
    <message>
        <source>None</source>
        <comment>glasses</comment>
        <translation>无</translation>
    </message>
    <message>
        <source>Round</source>
        <comment>glasses</comment>
        <translation>圆框</translation>
    </message>
    <message>
        <source>Rectangular</source>
        <comment>glasses</comment>
        <translation>方框</translation>
    </message>
    <message>
        <source>Rimless</source>
        <comment>glasses</comment>
        <translation>无框</translation>
    </message>
    <message>
        <source>landmark</source>
        <comment>detection method</comment>
        <translation>关键点</translation>
    </message>
    <message>
        <source>classic</source>
        <comment>detection method</comment>
        <translation>经典</translation>
    </message>
    <message>
        <source>Hair outline, point %1</source>
        <comment>a point of the face</comment>
        <translation>发际轮廓，第 %1 点</translation>
    </message>
    <message>
        <source>Left temple</source>
        <comment>a point of the face</comment>
        <translation>左太阳穴</translation>
    </message>
    <message>
        <source>Hairline, centre</source>
        <comment>a point of the face</comment>
        <translation>发际线中央</translation>
    </message>
    <message>
        <source>Right temple</source>
        <comment>a point of the face</comment>
        <translation>右太阳穴</translation>
    </message>
    <message>
        <source>Left cheek</source>
        <comment>a point of the face</comment>
        <translation>左脸颊</translation>
    </message>
    <message>
        <source>Right cheek</source>
        <comment>a point of the face</comment>
        <translation>右脸颊</translation>
    </message>
    <message>
        <source>Jaw, left, at the mouth</source>
        <comment>a point of the face</comment>
        <translation>下颌左侧，与嘴同高</translation>
    </message>
    <message>
        <source>Lower jaw, left</source>
        <comment>a point of the face</comment>
        <translation>下颌左下方</translation>
    </message>
    <message>
        <source>Chin</source>
        <comment>a point of the face</comment>
        <translation>下巴</translation>
    </message>
    <message>
        <source>Lower jaw, right</source>
        <comment>a point of the face</comment>
        <translation>下颌右下方</translation>
    </message>
    <message>
        <source>Jaw, right, at the mouth</source>
        <comment>a point of the face</comment>
        <translation>下颌右侧，与嘴同高</translation>
    </message>
    <message>
        <source>Left ear, top</source>
        <comment>a point of the face</comment>
        <translation>左耳，顶端</translation>
    </message>
    <message>
        <source>Left ear, outermost point</source>
        <comment>a point of the face</comment>
        <translation>左耳，最外侧</translation>
    </message>
    <message>
        <source>Left ear, bottom of the lobe</source>
        <comment>a point of the face</comment>
        <translation>左耳，耳垂底端</translation>
    </message>
    <message>
        <source>Left ear, where the lobe meets the cheek</source>
        <comment>a point of the face</comment>
        <translation>左耳，耳垂与脸颊交接处</translation>
    </message>
    <message>
        <source>Right ear, top</source>
        <comment>a point of the face</comment>
        <translation>右耳，顶端</translation>
    </message>
    <message>
        <source>Right ear, outermost point</source>
        <comment>a point of the face</comment>
        <translation>右耳，最外侧</translation>
    </message>
    <message>
        <source>Right ear, bottom of the lobe</source>
        <comment>a point of the face</comment>
        <translation>右耳，耳垂底端</translation>
    </message>
    <message>
        <source>Right ear, where the lobe meets the cheek</source>
        <comment>a point of the face</comment>
        <translation>右耳，耳垂与脸颊交接处</translation>
    </message>
    <message>
        <source>Left eyebrow, outer end</source>
        <comment>a point of the face</comment>
        <translation>左眉，外端</translation>
    </message>
    <message>
        <source>Left eyebrow, outer arch</source>
        <comment>a point of the face</comment>
        <translation>左眉，外侧眉峰</translation>
    </message>
    <message>
        <source>Left eyebrow, inner arch</source>
        <comment>a point of the face</comment>
        <translation>左眉，内侧眉峰</translation>
    </message>
    <message>
        <source>Left eyebrow, inner end</source>
        <comment>a point of the face</comment>
        <translation>左眉，内端</translation>
    </message>
    <message>
        <source>Right eyebrow, inner end</source>
        <comment>a point of the face</comment>
        <translation>右眉，内端</translation>
    </message>
    <message>
        <source>Right eyebrow, inner arch</source>
        <comment>a point of the face</comment>
        <translation>右眉，内侧眉峰</translation>
    </message>
    <message>
        <source>Right eyebrow, outer arch</source>
        <comment>a point of the face</comment>
        <translation>右眉，外侧眉峰</translation>
    </message>
    <message>
        <source>Right eyebrow, outer end</source>
        <comment>a point of the face</comment>
        <translation>右眉，外端</translation>
    </message>
    <message>
        <source>Left eye, outer corner</source>
        <comment>a point of the face</comment>
        <translation>左眼，外眼角</translation>
    </message>
    <message>
        <source>Left eye, upper lid</source>
        <comment>a point of the face</comment>
        <translation>左眼，上眼睑</translation>
    </message>
    <message>
        <source>Left eye, inner corner</source>
        <comment>a point of the face</comment>
        <translation>左眼，内眼角</translation>
    </message>
    <message>
        <source>Left eye, lower lid</source>
        <comment>a point of the face</comment>
        <translation>左眼，下眼睑</translation>
    </message>
    <message>
        <source>Left eye, centre of the eyeball</source>
        <comment>a point of the face</comment>
        <translation>左眼，眼球中心</translation>
    </message>
    <message>
        <source>Right eye, inner corner</source>
        <comment>a point of the face</comment>
        <translation>右眼，内眼角</translation>
    </message>
    <message>
        <source>Right eye, upper lid</source>
        <comment>a point of the face</comment>
        <translation>右眼，上眼睑</translation>
    </message>
    <message>
        <source>Right eye, outer corner</source>
        <comment>a point of the face</comment>
        <translation>右眼，外眼角</translation>
    </message>
    <message>
        <source>Right eye, lower lid</source>
        <comment>a point of the face</comment>
        <translation>右眼，下眼睑</translation>
    </message>
    <message>
        <source>Right eye, centre of the eyeball</source>
        <comment>a point of the face</comment>
        <translation>右眼，眼球中心</translation>
    </message>
    <message>
        <source>Bridge of the nose, left</source>
        <comment>a point of the face</comment>
        <translation>鼻梁，左侧</translation>
    </message>
    <message>
        <source>Bridge of the nose, right</source>
        <comment>a point of the face</comment>
        <translation>鼻梁，右侧</translation>
    </message>
    <message>
        <source>Nose, top left</source>
        <comment>a point of the face</comment>
        <translation>鼻子，左上方</translation>
    </message>
    <message>
        <source>Nose, top right</source>
        <comment>a point of the face</comment>
        <translation>鼻子，右上方</translation>
    </message>
    <message>
        <source>Nose, left wing</source>
        <comment>a point of the face</comment>
        <translation>鼻子，左鼻翼</translation>
    </message>
    <message>
        <source>Nose, right wing</source>
        <comment>a point of the face</comment>
        <translation>鼻子，右鼻翼</translation>
    </message>
    <message>
        <source>Left nostril, bottom</source>
        <comment>a point of the face</comment>
        <translation>左鼻孔，底部</translation>
    </message>
    <message>
        <source>Right nostril, bottom</source>
        <comment>a point of the face</comment>
        <translation>右鼻孔，底部</translation>
    </message>
    <message>
        <source>Tip of the nose</source>
        <comment>a point of the face</comment>
        <translation>鼻尖</translation>
    </message>
    <message>
        <source>Mouth, left corner</source>
        <comment>a point of the face</comment>
        <translation>嘴巴，左嘴角</translation>
    </message>
    <message>
        <source>Upper lip, left peak</source>
        <comment>a point of the face</comment>
        <translation>上唇，左唇峰</translation>
    </message>
    <message>
        <source>Upper lip, top centre</source>
        <comment>a point of the face</comment>
        <translation>上唇，上缘中央</translation>
    </message>
    <message>
        <source>Upper lip, right peak</source>
        <comment>a point of the face</comment>
        <translation>上唇，右唇峰</translation>
    </message>
    <message>
        <source>Mouth, right corner</source>
        <comment>a point of the face</comment>
        <translation>嘴巴，右嘴角</translation>
    </message>
    <message>
        <source>Lower lip, bottom centre</source>
        <comment>a point of the face</comment>
        <translation>下唇，下缘中央</translation>
    </message>
    <message>
        <source>Upper lip, inner edge</source>
        <comment>a point of the face</comment>
        <translation>上唇，内缘</translation>
    </message>
    <message>
        <source>Lower lip, inner edge</source>
        <comment>a point of the face</comment>
        <translation>下唇，内缘</translation>
    </message>
</context>
<context>
    <name>toonface::PhotoView</name>
    <message>
        <source>Another face in the photo: click to use it instead</source>
        <translation>照片中的另一张脸：单击改用它</translation>
    </message>
    <message>
        <source>Open a photo of a face (%1), or drop one here.</source>
        <translation>打开一张人脸照片（%1），或将照片拖放到这里。</translation>
    </message>
</context>
<context>
    <name>toonface::PlaybackController</name>
    <message>
        <source>&amp;Play</source>
        <translation>播放(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>Stop and return to the first frame</source>
        <translation>停止并回到第一帧</translation>
    </message>
    <message>
        <source>&amp;Loop</source>
        <translation>循环(&amp;L)</translation>
    </message>
    <message>
        <source>Loop: play from the start again at the end</source>
        <translation>循环：播放到结尾后从头再播</translation>
    </message>
    <message>
        <source>&amp;First Frame</source>
        <translation>第一帧(&amp;F)</translation>
    </message>
    <message>
        <source>Pre&amp;vious Frame</source>
        <translation>上一帧(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>下一帧(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Last Frame</source>
        <translation>最后一帧(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <source>%1 Playing without sound.</source>
        <translation>%1 无声播放。</translation>
    </message>
    <message>
        <source>The audio file %1 is missing: playing without sound.</source>
        <translation>找不到音频文件 %1：无声播放。</translation>
    </message>
    <message>
        <source>No audio output device: playing without sound.</source>
        <translation>没有音频输出设备：无声播放。</translation>
    </message>
    <message>
        <source>Nothing to play: the timeline is empty.</source>
        <translation>没有可播放的内容：时间轴是空的。</translation>
    </message>
</context>
<context>
    <name>toonface::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <source>System (%1)</source>
        <translation>系统（%1）</translation>
    </message>
    <message>
        <source>The new language shows when Toonface is started again.</source>
        <translation>新的语言将在下次启动 Toonface 时生效。</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
</context>
<context>
    <name>toonface::PreviewView</name>
    <message>
        <source>Edit &amp;Pose</source>
        <translation>编辑姿势(&amp;P)</translation>
    </message>
    <message>
        <source>Show the control points on the preview: drag one to set a pose key frame at the playhead</source>
        <translation>在预览上显示控制点：拖动其中一点即可在播放头处设置姿势关键帧</translation>
    </message>
    <message>
        <source>Open a photo to draw its cartoon.</source>
        <translation>打开照片以绘制它的卡通。</translation>
    </message>
    <message>
        <source>No face points yet.</source>
        <translation>还没有人脸特征点。</translation>
    </message>
    <message>
        <source>Drawing the cartoon…</source>
        <translation>正在绘制卡通…</translation>
    </message>
    <message>
        <source>&amp;Transparent Background</source>
        <translation>透明背景(&amp;T)</translation>
    </message>
    <message>
        <source>Show the cartoon without its background, over a checkerboard, as a transparent sticker exports it</source>
        <translation>把卡通画在棋盘格上、不含背景，就像导出的透明贴纸</translation>
    </message>
</context>
<context>
    <name>toonface::Problem</name>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <comment>two sentences one after the other</comment>
        <translation>%1%2</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between two reasons</comment>
        <translation>；</translation>
    </message>
</context>
<context>
    <name>toonface::ProjectFile</name>
    <message>
        <source>expected a number</source>
        <translation>应为数字</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>应为字符串</translation>
    </message>
    <message>
        <source>must not be negative</source>
        <translation>不能为负数</translation>
    </message>
    <message>
        <source>must be positive</source>
        <translation>必须为正数</translation>
    </message>
    <message>
        <source>must be between 0 and 1</source>
        <translation>必须介于 0 和 1 之间</translation>
    </message>
    <message>
        <source>%1: expected an array</source>
        <translation>%1：应为数组</translation>
    </message>
    <message>
        <source>%1: expected an object</source>
        <translation>%1：应为对象</translation>
    </message>
    <message>
        <source>expected a positive integer</source>
        <translation>应为正整数</translation>
    </message>
    <message>
        <source>%1 is newer than this Toonface reads (%2)</source>
        <translation>%1 比这个 Toonface 能读取的版本（%2）更新</translation>
    </message>
    <message>
        <source>smoothing: expected an object</source>
        <translation>smoothing：应为对象</translation>
    </message>
    <message>
        <source>unknown mouth shape &apos;%1&apos;</source>
        <translation>未知的口型“%1”</translation>
    </message>
    <message>
        <source>must not be before start</source>
        <translation>不能早于 start</translation>
    </message>
    <message>
        <source>unknown emotion &apos;%1&apos;</source>
        <translation>未知的表情“%1”</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>应为对象</translation>
    </message>
    <message>
        <source>unknown point ID</source>
        <translation>未知的特征点 ID</translation>
    </message>
    <message>
        <source>expected [dx, dy], two numbers</source>
        <translation>应为 [dx, dy] 两个数字</translation>
    </message>
    <message>
        <source>video: expected an object</source>
        <translation>video：应为对象</translation>
    </message>
    <message>
        <source>an [x, y] pair</source>
        <translation>一组 [x, y]</translation>
    </message>
    <message>
        <source>a box of negative size</source>
        <translation>方框的尺寸为负数</translation>
    </message>
    <message>
        <source>two boxes, image-left first</source>
        <translation>两个方框，图像左侧的在前</translation>
    </message>
    <message>
        <source>two eyeballs, image-left first</source>
        <translation>两个眼球，图像左侧的在前</translation>
    </message>
    <message>
        <source>four edge thresholds, top part first</source>
        <translation>四个边缘阈值，上半部的在前</translation>
    </message>
    <message>
        <source>%1 was made by a newer Toonface (this version reads %2)</source>
        <translation>%1 是由较新版的 Toonface 创建的（此版本读取 %2）</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>数字</translation>
    </message>
    <message>
        <source>a finite number</source>
        <translation>有限的数字</translation>
    </message>
    <message>
        <source>a number between %1 and %2</source>
        <translation>介于 %1 和 %2 之间的数字</translation>
    </message>
    <message>
        <source>an integer from %1 to %2</source>
        <translation>%1 到 %2 的整数</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>a string</source>
        <translation>字符串</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>an array</source>
        <translation>数组</translation>
    </message>
    <message>
        <source>expected %1, %2</source>
        <translation>应为%1，%2</translation>
    </message>
    <message>
        <source>it is missing</source>
        <translation>但缺少此项</translation>
    </message>
    <message>
        <source>found null</source>
        <translation>实际为 null</translation>
    </message>
    <message>
        <source>found true</source>
        <translation>实际为 true</translation>
    </message>
    <message>
        <source>found false</source>
        <translation>实际为 false</translation>
    </message>
    <message>
        <source>found %1</source>
        <translation>实际为 %1</translation>
    </message>
    <message>
        <source>found the string &quot;%1&quot;</source>
        <translation>实际为字符串“%1”</translation>
    </message>
    <message>
        <source>found an array</source>
        <translation>实际为数组</translation>
    </message>
    <message>
        <source>found an object</source>
        <translation>实际为对象</translation>
    </message>
    <message>
        <source>a width more than 0</source>
        <translation>大于 0 的宽度</translation>
    </message>
    <message>
        <source>not an SVG drawing: %1</source>
        <translation>不是 SVG 绘图：%1</translation>
    </message>
    <message>
        <source>one of %1</source>
        <translation>下列之一：%1</translation>
    </message>
    <message>
        <source>a colour like #rrggbb or #aarrggbb, or &quot;none&quot;</source>
        <translation>#rrggbb 或 #aarrggbb 形式的颜色，或“none”</translation>
    </message>
    <message>
        <source>a number from 0 to %1</source>
        <translation>0 到 %1 的数字</translation>
    </message>
    <message>
        <source>a component needs a name</source>
        <translation>组件需要名称</translation>
    </message>
    <message>
        <source>a width of 0 or more</source>
        <translation>0 或以上的宽度</translation>
    </message>
    <message>
        <source>unknown mouth shape (the shapes are %1)</source>
        <translation>未知的口型（口型有 %1）</translation>
    </message>
    <message>
        <source>not a Toonface project (it has no &quot;format&quot; field)</source>
        <translation>不是 Toonface 项目（没有“format”字段）</translation>
    </message>
    <message>
        <source>not a Toonface project (format: expected &quot;%1&quot;, %2)</source>
        <translation>不是 Toonface 项目（format：应为“%1”，%2）</translation>
    </message>
    <message>
        <source>a version number (1 or more)</source>
        <translation>版本号（1 或以上）</translation>
    </message>
    <message>
        <source>made by a newer Toonface (project version %1; this version reads up to %2)</source>
        <translation>由较新版的 Toonface 创建（项目版本 %1；此版本最多读取到 %2）</translation>
    </message>
    <message>
        <source>a file path</source>
        <translation>文件路径</translation>
    </message>
    <message>
        <source>not saved: the project is invalid at %1</source>
        <translation>未保存：项目在 %1 处无效</translation>
    </message>
    <message>
        <source>cannot save: %1</source>
        <translation>无法保存：%1</translation>
    </message>
    <message>
        <source>only %1 of %2 bytes could be written (is the disk full?)</source>
        <translation>%2 字节中只写入了 %1 字节（磁盘是否已满？）</translation>
    </message>
    <message>
        <source>the file could not be completed (is the disk full?)</source>
        <translation>无法完成文件（磁盘是否已满？）</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <source>is a folder, not a Toonface project</source>
        <translation>这是文件夹，不是 Toonface 项目</translation>
    </message>
    <message>
        <source>too large to be a Toonface project (%1 MB)</source>
        <translation>文件太大，不可能是 Toonface 项目（%1 MB）</translation>
    </message>
    <message>
        <source>cannot read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>the file is empty, not a Toonface project</source>
        <translation>文件是空的，不是 Toonface 项目</translation>
    </message>
    <message>
        <source>not a Toonface project: %1 at offset %2 (line %3, column %4)</source>
        <translation>不是 Toonface 项目：偏移 %2 处%1（第 %3 行第 %4 列）</translation>
    </message>
    <message>
        <source>not a Toonface project (expected a JSON object, found an array)</source>
        <translation>不是 Toonface 项目（应为 JSON 对象，实际为数组）</translation>
    </message>
    <message>
        <source>%1 s is outside the syllable (%2 to %3 s) or before the shape before it</source>
        <translation>%1 秒超出音节范围（%2 到 %3 秒），或早于前一个口型</translation>
    </message>
    <message>
        <source>a time of 0 s or more</source>
        <translation>0 秒或以上的时间</translation>
    </message>
    <message>
        <source>a time after the start (%1 s)</source>
        <translation>开始时间（%1 秒）之后的时间</translation>
    </message>
    <message>
        <source>expected %1 points, found %2</source>
        <translation>应有 %1 个点，实际有 %2 个</translation>
    </message>
    <message>
        <source>&quot;cmn&quot;, &quot;en&quot; or &quot;&quot;</source>
        <translation>“cmn”、“en”或“”</translation>
    </message>
    <message>
        <source>%1 s is beyond the longest timeline Toonface keeps (%2 hours)</source>
        <translation>%1 秒超出 Toonface 时间轴的最长长度（%2 小时）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>photo</source>
        <translation>照片</translation>
    </message>
    <message>
        <source>sound</source>
        <translation>声音</translation>
    </message>
    <message>
        <source>video</source>
        <translation>视频</translation>
    </message>
    <message>
        <source>layer</source>
        <translation>图层</translation>
    </message>
    <message>
        <source>is a folder, not a file</source>
        <translation>是文件夹，不是文件</translation>
    </message>
    <message>
        <source>is a device, a pipe or a socket, not a file</source>
        <translation>是设备、管道或套接字，不是文件</translation>
    </message>
    <message>
        <source>too large (more than %1 MB)</source>
        <translation>太大（超过 %1 MB）</translation>
    </message>
    <message>
        <source>no space left on the disk (%1 KB free on %2)</source>
        <translation>磁盘已无空间（%2 上只剩 %1 KB）</translation>
    </message>
    <message>
        <source>the system gave no reason (is the disk full or removed?)</source>
        <translation>系统未说明原因（磁盘是否已满或已移除？）</translation>
    </message>
    <message>
        <source>the trims are longer than the recording</source>
        <translation>修剪的长度超过录音本身</translation>
    </message>
    <message>
        <source>the clip ends beyond the longest timeline Toonface keeps (%1 hours)</source>
        <translation>片段的结尾超出 Toonface 所能保存的最长时间轴（%1 小时）</translation>
    </message>
    <message>
        <source>expected &quot;cmn&quot;, &quot;en&quot; or &quot;&quot;</source>
        <translation>应为 &quot;cmn&quot;、&quot;en&quot; 或 &quot;&quot;</translation>
    </message>
    <message>
        <source>audio: expected an array of clips</source>
        <translation>audio：应为片段的数组</translation>
    </message>
</context>
<context>
    <name>toonface::Questions</name>
    <message>
        <source>an untitled project</source>
        <translation>一个未命名的项目</translation>
    </message>
    <message>
        <source>Restore Unsaved Work</source>
        <translation>恢复未保存的工作</translation>
    </message>
    <message>
        <source>Toonface did not close properly. Unsaved work on %1 from %2 was kept.</source>
        <translation>Toonface 上次没有正常关闭。已保留 %2 时 %1 未保存的工作。</translation>
    </message>
    <message>
        <source>Restore it? Discarding deletes the kept copy.</source>
        <translation>要恢复吗？丢弃会删除保留的副本。</translation>
    </message>
    <message>
        <source>&amp;Restore</source>
        <translation>恢复(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>丢弃(&amp;D)</translation>
    </message>
    <message>
        <source>No face was found in %1.</source>
        <translation>在 %1 中找不到人脸。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>No Face Found</source>
        <translation>找不到人脸</translation>
    </message>
    <message>
        <source>You can place an average face on the photo and drag its points into place by hand.</source>
        <translation>您可以在照片上放一张平均脸，再手动把特征点拖动到正确位置。</translation>
    </message>
    <message>
        <source>&amp;Place Average Face</source>
        <translation>放置平均脸(&amp;P)</translation>
    </message>
    <message>
        <source>Place average face</source>
        <translation>放置平均脸</translation>
    </message>
    <message>
        <source>Files Outside the Project</source>
        <translation>项目文件夹以外的文件</translation>
    </message>
    <message>
        <source>%1 uses files outside its folder. Its sound, photo, video and layers are read from there when you play or export it:</source>
        <translation>%1 使用了其文件夹以外的文件。播放或导出时，会从这些位置读取它的声音、照片、视频和图层：</translation>
    </message>
    <message>
        <source>Project Changed on Disk</source>
        <translation>项目已在磁盘上更改</translation>
    </message>
    <message>
        <source>%1 was changed by another program since you opened it.</source>
        <translation>自您打开后，%1 已被其他程序更改。</translation>
    </message>
    <message>
        <source>Overwriting it loses the other program&apos;s changes.</source>
        <translation>覆盖会丢失其他程序所做的更改。</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Overwrite</source>
        <translation>覆盖(&amp;O)</translation>
    </message>
    <message>
        <source>Re-detect Points</source>
        <translation>重新检测特征点</translation>
    </message>
    <message numerus="yes">
        <source>You moved %n point(s) by hand. Re-detecting replaces every point.</source>
        <translation>
            <numerusform>您手动移动了 %n 个特征点。重新检测会替换所有特征点。</numerusform>
        </translation>
    </message>
    <message>
        <source>Keep the points you moved, or replace them with the detected ones?</source>
        <translation>保留您移动的特征点，还是用检测到的特征点替换？</translation>
    </message>
    <message>
        <source>&amp;Keep My Points</source>
        <translation>保留我的特征点(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;Replace Them</source>
        <translation>替换它们(&amp;R)</translation>
    </message>
</context>
<context>
    <name>toonface::SayTextDialog</name>
    <message>
        <source>Say</source>
        <translation>朗读</translation>
    </message>
    <message>
        <source>Say Text</source>
        <translation>说出文字</translation>
    </message>
    <message>
        <source>Chinese characters, pinyin, Zhuyin or English, e.g. 您好，我是葛麗絲。</source>
        <translation>汉字、拼音、注音或英文，例如：您好，我是葛丽丝。</translation>
    </message>
    <message>
        <source> words/min</source>
        <translation> 字/分钟</translation>
    </message>
    <message>
        <source>Where the speech starts on the timeline</source>
        <translation>语音在时间轴上的开始位置</translation>
    </message>
    <message>
        <source>Pitch:</source>
        <translation>音高：</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <source>The sound is saved beside the project.</source>
        <translation>声音会保存在项目旁边。</translation>
    </message>
    <message>
        <source>The project is not saved yet: the sound is saved in your documents folder.</source>
        <translation>项目尚未保存：声音会保存在您的文档文件夹中。</translation>
    </message>
    <message>
        <source>The project is not saved yet: the sound is saved beside the photo. Save the project in the same folder to keep them together.</source>
        <translation>项目尚未保存：声音会保存在照片旁边。请将项目保存在同一个文件夹中，让它们放在一起。</translation>
    </message>
    <message>
        <source>&amp;Text:</source>
        <translation>文字(&amp;T)：</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>速度(&amp;S)：</translation>
    </message>
    <message>
        <source>Starts &amp;at:</source>
        <translation>开始于(&amp;A)：</translation>
    </message>
    <message>
        <source>Save the s&amp;ound as:</source>
        <translation>声音保存为(&amp;O)：</translation>
    </message>
    <message>
        <source>Save the Sound As</source>
        <translation>声音另存为</translation>
    </message>
    <message>
        <source>WAV sound (*.wav)</source>
        <translation>WAV 声音 (*.wav)</translation>
    </message>
    <message>
        <source>The text has nothing to say.</source>
        <translation>文字中没有可说的内容。</translation>
    </message>
    <message>
        <source>Speaking</source>
        <translation>正在朗读</translation>
    </message>
    <message>
        <source>%1: cannot create its folder</source>
        <translation>%1：无法创建其文件夹</translation>
    </message>
    <message>
        <source>The built-in voice speaks the text and the face says it with the voice&apos;s exact timings. The speech becomes a clip on the audio track; the mouth keys and syllables where it plays are replaced, the other recordings are kept.</source>
        <translation>内置语音朗读文字，脸部按语音的精确时间说出。语音成为音轨上的一个片段；其播放范围内的口型关键帧与音节会被替换，其他录音都会保留。</translation>
    </message>
</context>
<context>
    <name>toonface::Script</name>
    <message>
        <source>no reference rendering of the script</source>
        <translation>没有文稿的参考朗读</translation>
    </message>
    <message>
        <source>no speech found in the audio</source>
        <translation>音频中找不到说话声</translation>
    </message>
    <message>
        <source>the script is far too long for the audio: its %1 syllables need about %2 s of speech, the audio holds %3 s</source>
        <translation>文稿对这段音频来说太长：%1 个音节约需 %2 秒的语音，音频只有 %3 秒</translation>
    </message>
    <message>
        <source>the audio holds far more speech (%1 s) than the script&apos;s %2 syllables (about %3 s)</source>
        <translation>音频中的语音（%1 秒）远多于文稿的 %2 个音节（约 %3 秒）</translation>
    </message>
    <message>
        <source>the audio and the script could not be matched</source>
        <translation>无法将音频与文稿对应</translation>
    </message>
    <message>
        <source>the script is empty</source>
        <translation>文稿是空的</translation>
    </message>
    <message>
        <source>the audio is empty</source>
        <translation>音频是空的</translation>
    </message>
    <message>
        <source>%1 and %2 could not be aligned: %3</source>
        <translation>无法对齐 %1 和 %2：%3</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>无法读取 %1</translation>
    </message>
    <message>
        <source>cannot start bzip2 decompression of %1</source>
        <translation>无法开始以 bzip2 解压 %1</translation>
    </message>
    <message>
        <source>%1 is not a valid bzip2 file</source>
        <translation>%1 不是有效的 bzip2 文件</translation>
    </message>
    <message>
        <source>Chinese character readings are missing (%1; install the Debian package unicode-data)</source>
        <translation>缺少汉字读音（%1；请安装 Debian 软件包 unicode-data）</translation>
    </message>
    <message>
        <source>%1 holds no Mandarin readings</source>
        <translation>%1 中没有普通话读音</translation>
    </message>
    <message>
        <source>the phrase dictionary %1 is missing (install the Debian package rime-data-terra-pinyin)</source>
        <translation>缺少词语词典 %1（请安装 Debian 软件包 rime-data-terra-pinyin）</translation>
    </message>
    <message>
        <source>%1: built from other sources</source>
        <translation>%1：由其他来源生成</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>too short to be a pinyin index</source>
        <translation>太短，不可能是拼音索引</translation>
    </message>
    <message>
        <source>not a pinyin index</source>
        <translation>不是拼音索引</translation>
    </message>
    <message>
        <source>pinyin index format %1, expected %2</source>
        <translation>拼音索引格式为 %1，应为 %2</translation>
    </message>
    <message>
        <source>pinyin index of %1 bytes, its header describes %2</source>
        <translation>拼音索引有 %1 字节，但文件头记载 %2</translation>
    </message>
    <message>
        <source>pinyin index checksum mismatch (damaged)</source>
        <translation>拼音索引校验和不符（已损坏）</translation>
    </message>
    <message>
        <source>pinyin index has a bad syllable &apos;%1&apos;</source>
        <translation>拼音索引中有错误的音节“%1”</translation>
    </message>
    <message>
        <source>pinyin index syllable table is damaged</source>
        <translation>拼音索引的音节表已损坏</translation>
    </message>
    <message>
        <source>pinyin index character table is damaged</source>
        <translation>拼音索引的字符表已损坏</translation>
    </message>
    <message>
        <source>pinyin index character readings are damaged</source>
        <translation>拼音索引的字符读音已损坏</translation>
    </message>
    <message>
        <source>pinyin index phrase table is damaged</source>
        <translation>拼音索引的词语表已损坏</translation>
    </message>
    <message>
        <source>pinyin index phrase readings are damaged</source>
        <translation>拼音索引的词语读音已损坏</translation>
    </message>
    <message>
        <source>cannot be spoken</source>
        <translation>无法朗读</translation>
    </message>
    <message>
        <source>is not English</source>
        <translation>不是英文</translation>
    </message>
    <message>
        <source>has no Mandarin reading in the dictionary</source>
        <translation>在词典中没有普通话读音</translation>
    </message>
    <message>
        <source>is not valid Zhuyin</source>
        <translation>不是有效的注音</translation>
    </message>
    <message>
        <source>is a number: write it in characters or pinyin</source>
        <translation>是数字：请用汉字或拼音书写</translation>
    </message>
    <message>
        <source>is not Hanyu pinyin</source>
        <translation>不是汉语拼音</translation>
    </message>
    <message>
        <source>line %1, column %2: &apos;%3&apos; %4</source>
        <translation>第 %1 行第 %2 列：“%3”%4</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1（另有 %n 处）</numerusform>
        </translation>
    </message>
    <message>
        <source>the script holds nothing to speak</source>
        <translation>文稿中没有可朗读的内容</translation>
    </message>
    <message>
        <source>cannot read the script %1: %2</source>
        <translation>无法读取文稿 %1：%2</translation>
    </message>
    <message>
        <source>the script %1 is not UTF-8 text</source>
        <translation>文稿 %1 不是 UTF-8 文本</translation>
    </message>
    <message>
        <source>espeak-ng cannot start: its data is missing (install espeak-ng-data)</source>
        <translation>espeak-ng 无法启动：缺少数据（请安装 espeak-ng-data）</translation>
    </message>
    <message>
        <source>nothing to speak</source>
        <translation>没有可朗读的内容</translation>
    </message>
    <message>
        <source>espeak-ng has no voice &apos;%1&apos;</source>
        <translation>espeak-ng 没有“%1”语音</translation>
    </message>
    <message>
        <source>espeak-ng could not speak the script</source>
        <translation>espeak-ng 无法朗读文稿</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
</context>
<context>
    <name>toonface::SecondsBox</name>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
</context>
<context>
    <name>toonface::ShapePalette</name>
    <message>
        <source>Mouth shape %1 (key %2): replaces the selected mouth keys, or inserts one at the playhead</source>
        <translation>口型 %1（按键 %2）：替换所选的口型关键帧，或在播放头处插入一个</translation>
    </message>
</context>
<context>
    <name>toonface::ShortcutsDialog</name>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>Timeline (while it has focus)</source>
        <translation>时间轴（获得焦点时）</translation>
    </message>
    <message>
        <source>Set or insert a mouth shape</source>
        <translation>设置或插入口型</translation>
    </message>
    <message>
        <source>Zoom in, out, to fit</source>
        <translation>放大、缩小、缩放至适合</translation>
    </message>
    <message>
        <source>Zoom about the pointer</source>
        <translation>以指针为中心缩放</translation>
    </message>
    <message>
        <source>Ctrl+wheel</source>
        <translation>Ctrl+滚轮</translation>
    </message>
    <message>
        <source>Scroll the rows</source>
        <translation>滚动各行</translation>
    </message>
    <message>
        <source>Shift+wheel</source>
        <translation>Shift+滚轮</translation>
    </message>
    <message>
        <source>Waveform taller or shorter</source>
        <translation>波形加高或降低</translation>
    </message>
    <message>
        <source>Alt+wheel</source>
        <translation>Alt+滚轮</translation>
    </message>
    <message>
        <source>Edit a syllable&apos;s pinyin</source>
        <translation>编辑音节的拼音</translation>
    </message>
    <message>
        <source>Double-click</source>
        <translation>双击</translation>
    </message>
</context>
<context>
    <name>toonface::SoundFile</name>
    <message>
        <source>cannot read the audio: %1</source>
        <translation>无法读取音频：%1</translation>
    </message>
    <message>
        <source>no audio stream</source>
        <translation>没有音频流</translation>
    </message>
    <message>
        <source>audio samples</source>
        <translation>音频采样</translation>
    </message>
    <message>
        <source>invalid sample rate %1</source>
        <translation>无效的采样率 %1</translation>
    </message>
    <message>
        <source>the audio has no sample rate</source>
        <translation>音频没有采样率</translation>
    </message>
    <message>
        <source>cannot resample the audio: %1</source>
        <translation>无法重采样音频：%1</translation>
    </message>
    <message>
        <source>cannot decode the audio: %1</source>
        <translation>无法解码音频：%1</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>文件是空的</translation>
    </message>
    <message>
        <source>not a readable sound or video file (%1)</source>
        <translation>不是可读取的声音或视频文件（%1）</translation>
    </message>
    <message>
        <source>cannot read its streams (%1)</source>
        <translation>无法读取其中的流（%1）</translation>
    </message>
    <message>
        <source>no decoder for its sound track</source>
        <translation>没有可解码其音轨的解码器</translation>
    </message>
    <message>
        <source>it has no sound track</source>
        <translation>其中没有音轨</translation>
    </message>
    <message>
        <source>cannot open the %1 decoder</source>
        <translation>无法打开 %1 解码器</translation>
    </message>
    <message>
        <source>cannot convert its samples</source>
        <translation>无法转换其采样</translation>
    </message>
    <message>
        <source>its sound track cannot be decoded (corrupt data)</source>
        <translation>其音轨无法解码（数据损坏）</translation>
    </message>
    <message>
        <source>it holds no sound</source>
        <translation>其中没有声音</translation>
    </message>
    <message>
        <source>it is silent (peak %1 dBFS)</source>
        <translation>是静音的（峰值 %1 dBFS）</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>unknown sound format &apos;.%1&apos; (use wav, flac, mp3, ogg, opus or m4a)</source>
        <translation>未知的声音格式“.%1”（请使用 wav、flac、mp3、ogg、opus 或 m4a）</translation>
    </message>
    <message>
        <source>this FFmpeg has no encoder for .%1</source>
        <translation>此 FFmpeg 没有 .%1 的编码器</translation>
    </message>
    <message>
        <source>no container for .%1</source>
        <translation>没有 .%1 的容器格式</translation>
    </message>
    <message>
        <source>cannot open the %1 encoder (%2)</source>
        <translation>无法打开 %1 编码器（%2）</translation>
    </message>
    <message>
        <source>cannot add a sound stream</source>
        <translation>无法添加声音流</translation>
    </message>
    <message>
        <source>cannot convert the samples</source>
        <translation>无法转换采样</translation>
    </message>
    <message>
        <source>encoding failed</source>
        <translation>编码失败</translation>
    </message>
    <message>
        <source>its sample rate (%1 Hz) is too low for speech (at least %2 Hz)</source>
        <translation>其采样率（%1 Hz）太低，不足以承载语音（至少需要 %2 Hz）</translation>
    </message>
    <message>
        <source>it is damaged: it decodes to more than %1 s of sound, more than its %2 bytes can hold</source>
        <translation>文件已损坏：解码出超过 %1 秒的声音，超出其 %2 字节所能容纳的长度</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>holds no sound</source>
        <translation>没有声音</translation>
    </message>
    <message>
        <source>no room for a temporary copy of the sound: %1</source>
        <translation>没有空间存放声音的临时副本：%1</translation>
    </message>
    <message>
        <source>the sound cannot be used: %1</source>
        <translation>无法使用这个声音：%1</translation>
    </message>
    <message>
        <source>cut short (its header promises %1 s, it holds %2 s)</source>
        <translation>文件不完整（文件头记载 %1 秒，实际只有 %2 秒）</translation>
    </message>
    <message>
        <source>the sound of several or trimmed recordings can only be embedded, not referenced</source>
        <translation>多段或经修剪的录音只能内嵌，不能以引用方式使用</translation>
    </message>
    <message>
        <source>the writer is closed</source>
        <translation>写入器已关闭</translation>
    </message>
    <message>
        <source>no samples in %1 packets</source>
        <translation>%1 个数据包中没有任何样本</translation>
    </message>
    <message>
        <source>the sound does not decode at %1 s: %2</source>
        <translation>声音在 %1 秒处无法解码：%2</translation>
    </message>
    <message>
        <source>too long for a WAV file</source>
        <translation>对 WAV 文件来说太长</translation>
    </message>
</context>
<context>
    <name>toonface::SpeechDialog</name>
    <message>
        <source>Nothing was changed.</source>
        <translation>没有任何更改。</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Cancelled: nothing was changed.</source>
        <translation>已取消：没有任何更改。</translation>
    </message>
    <message>
        <source>Place it after them</source>
        <translation>放在它们之后</translation>
    </message>
    <message>
        <source>Replace them (with their syllables and mouth keys)</source>
        <translation>替换它们（连同其音节与口型关键帧）</translation>
    </message>
    <message>
        <source>The timeline keeps every recording as a clip on the audio track. What to do when the new one would play over others: nothing is replaced unless you choose so.</source>
        <translation>时间轴将每段录音保存为音轨上的片段。新录音会与其他录音重叠时的做法：除非您选择替换，否则不会替换任何录音。</translation>
    </message>
    <message>
        <source>If other recordings &amp;play there:</source>
        <translation>若该处已有其他录音(&amp;P)：</translation>
    </message>
    <message>
        <source>%1 (%2 s) does not fit on the timeline there: it would end past %3 hours.</source>
        <translation>%1（%2 秒）放不进时间轴的该处：结尾会超过 %3 小时。</translation>
    </message>
    <message>
        <source>%1: %2 at %3 s</source>
        <translation>%1：%2 位于 %3 秒</translation>
    </message>
</context>
<context>
    <name>toonface::StepImageDialog</name>
    <message>
        <source>No picture.</source>
        <translation>没有画面。</translation>
    </message>
</context>
<context>
    <name>toonface::Studio</name>
    <message>
        <source>&amp;Lip Sync from Recording…</source>
        <translation>根据录音做口型同步(&amp;L)…</translation>
    </message>
    <message>
        <source>Time the mouth to a speech recording and its script</source>
        <translation>让嘴巴配合语音录音及其文稿的时间</translation>
    </message>
    <message>
        <source>&amp;Say Text…</source>
        <translation>说出文字(&amp;S)…</translation>
    </message>
    <message>
        <source>Speak a text with the built-in voice and lip-sync the face to it</source>
        <translation>用内置语音朗读文字，并让人脸对口型</translation>
    </message>
    <message>
        <source>Add &amp;Blinks…</source>
        <translation>添加眨眼(&amp;B)…</translation>
    </message>
    <message>
        <source>Add &amp;Emotion…</source>
        <translation>添加表情(&amp;E)…</translation>
    </message>
    <message>
        <source>&amp;Mouth Shapes…</source>
        <translation>口型(&amp;M)…</translation>
    </message>
    <message>
        <source>Edit this character&apos;s nine mouth shapes</source>
        <translation>编辑这个角色的九种口型</translation>
    </message>
    <message>
        <source>Export &amp;Animation…</source>
        <translation>导出动画(&amp;A)…</translation>
    </message>
    <message>
        <source>Export the animation as SVG, HTML, MP4, GIF or PNG frames</source>
        <translation>将动画导出为 SVG、HTML、MP4、GIF 或 PNG 帧</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>动画(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Timeline</source>
        <translation>时间轴(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>播放(&amp;P)</translation>
    </message>
    <message>
        <source>Transport</source>
        <translation>播放控制</translation>
    </message>
    <message>
        <source>Import &amp;Video…</source>
        <translation>导入视频(&amp;V)…</translation>
    </message>
    <message>
        <source>Track a clip of a person speaking and put the motion on the timeline</source>
        <translation>跟踪人物说话的片段，并将动作放到时间轴上</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>已导入 %1</translation>
    </message>
    <message>
        <source>Show the imported clip beside the cartoon</source>
        <translation>在卡通旁显示导入的片段</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>首选项(&amp;F)…</translation>
    </message>
    <message>
        <source>Choose the language of the interface</source>
        <translation>选择界面的语言</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>已导出 %1</translation>
    </message>
    <message>
        <source>Capture from &amp;Camera…</source>
        <translation>从摄像头拍摄(&amp;C)…</translation>
    </message>
    <message>
        <source>Take the neutral photo with a camera</source>
        <translation>用摄像头拍摄中性照片</translation>
    </message>
    <message>
        <source>&amp;Live Mode…</source>
        <translation>实时模式(&amp;L)…</translation>
    </message>
    <message>
        <source>Puppeteer the cartoon live from a camera or a video, and record the performance</source>
        <translation>用摄像头或视频实时操控卡通，并录制表演</translation>
    </message>
    <message>
        <source>Camera photo saved as %1</source>
        <translation>摄像头照片已保存为 %1</translation>
    </message>
    <message>
        <source>Imported %1 with its sound as a clip on the audio track</source>
        <translation>已导入 %1，其声音成为音轨上的片段</translation>
    </message>
</context>
<context>
    <name>toonface::TimeReadout</name>
    <message>
        <source>The playhead&apos;s time and frame</source>
        <translation>播放头的时间和帧</translation>
    </message>
    <message>
        <source>%1:%2.%3  frame %4 / %5</source>
        <translation>%1:%2.%3  第 %4 / %5 帧</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>时间轴</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineEdits</name>
    <message>
        <source>the clipboard holds no timeline items</source>
        <translation>剪贴板中没有时间轴项目</translation>
    </message>
    <message>
        <source>the clipboard&apos;s timeline items are damaged: %1</source>
        <translation>剪贴板中的时间轴项目已损坏：%1</translation>
    </message>
    <message>
        <source>no syllable %1</source>
        <translation>没有第 %1 个音节</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an English word: it has no pinyin</source>
        <translation>“%1”是英文单词：没有拼音</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a Mandarin syllable</source>
        <translation>“%1”不是普通话音节</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineView</name>
    <message>
        <source>Reading the sound…</source>
        <translation>正在读取声音…</translation>
    </message>
    <message>
        <source>Move on Timeline</source>
        <translation>在时间轴上移动</translation>
    </message>
    <message>
        <source>Retime Syllable</source>
        <translation>调整音节时间</translation>
    </message>
    <message>
        <source>Resize on Timeline</source>
        <translation>在时间轴上调整长度</translation>
    </message>
    <message>
        <source>Change Emotion Fade</source>
        <translation>更改表情淡入淡出</translation>
    </message>
    <message>
        <source>Change Emotion Intensity</source>
        <translation>更改表情强度</translation>
    </message>
    <message>
        <source>Change Mouth Weight</source>
        <translation>更改口型权重</translation>
    </message>
    <message>
        <source>Delete from Timeline</source>
        <translation>从时间轴删除</translation>
    </message>
    <message>
        <source>Paste on Timeline</source>
        <translation>粘贴到时间轴</translation>
    </message>
    <message>
        <source>Replace Mouth Shape</source>
        <translation>替换口型</translation>
    </message>
    <message>
        <source>Insert Mouth Shape</source>
        <translation>插入口型</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>添加表情</translation>
    </message>
    <message>
        <source>Regenerate Blinks</source>
        <translation>重新生成眨眼</translation>
    </message>
    <message>
        <source>Add Head Shake</source>
        <translation>添加摇头</translation>
    </message>
    <message>
        <source>Add Head Nod</source>
        <translation>添加点头</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an English word: only Mandarin syllables have pinyin to edit</source>
        <translation>“%1”是英文单词：只有普通话音节才有可编辑的拼音</translation>
    </message>
    <message>
        <source>Change Syllable</source>
        <translation>更改音节</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineWidget</name>
    <message>
        <source>Emotion</source>
        <translation>表情</translation>
    </message>
    <message>
        <source>Mouth</source>
        <translation>口型</translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation>放大</translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation>缩小</translation>
    </message>
    <message>
        <source>Zoom to Fit</source>
        <translation>缩放到适合大小</translation>
    </message>
    <message>
        <source>Snap to Frames and Syllables</source>
        <translation>对齐帧和音节</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Copy Keys</source>
        <translation>复制关键帧</translation>
    </message>
    <message>
        <source>Paste Keys at Playhead</source>
        <translation>在播放头处粘贴关键帧</translation>
    </message>
    <message>
        <source>Select All in Row</source>
        <translation>选择整行</translation>
    </message>
    <message>
        <source>Regenerate Blinks</source>
        <translation>重新生成眨眼</translation>
    </message>
    <message>
        <source>Add Head Shake</source>
        <translation>添加摇头</translation>
    </message>
    <message>
        <source>Add Head Nod</source>
        <translation>添加点头</translation>
    </message>
    <message>
        <source>Apply %1</source>
        <translation>应用%1</translation>
    </message>
    <message>
        <source>Replace Shape</source>
        <translation>替换口型</translation>
    </message>
    <message>
        <source>Insert Shape</source>
        <translation>插入口型</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>粗细</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>添加表情</translation>
    </message>
    <message>
        <source>Edit Pinyin…</source>
        <translation>编辑拼音…</translation>
    </message>
    <message>
        <source>Taller Waveform</source>
        <translation>加高波形</translation>
    </message>
    <message>
        <source>Shorter Waveform</source>
        <translation>降低波形</translation>
    </message>
    <message>
        <source> (Alt+wheel)</source>
        <translation>（Alt+滚轮）</translation>
    </message>
    <message>
        <source>Emotion Intensity</source>
        <translation>表情强度</translation>
    </message>
    <message>
        <source>Intensity of %1 (%):</source>
        <translation>%1的强度（%）：</translation>
    </message>
    <message>
        <source>Intensity…</source>
        <translation>强度…</translation>
    </message>
</context>
<context>
    <name>toonface::VideoDock</name>
    <message>
        <source>Video</source>
        <translation>视频</translation>
    </message>
</context>
<context>
    <name>toonface::VideoFile</name>
    <message>
        <source>no decoder for its %1 codec &apos;%2&apos;</source>
        <translation>没有其 %1 编解码器“%2”的解码器</translation>
    </message>
    <message>
        <source>cannot open its %1 decoder: %2</source>
        <translation>无法打开其 %1 解码器：%2</translation>
    </message>
    <message>
        <source>no frame_NNNNN.png files in the folder</source>
        <translation>文件夹中没有 frame_NNNNN.png 文件</translation>
    </message>
    <message>
        <source>cannot read the streams: %1</source>
        <translation>无法读取流：%1</translation>
    </message>
    <message>
        <source>no video or audio stream</source>
        <translation>没有视频或音频流</translation>
    </message>
    <message>
        <source>no video stream</source>
        <translation>没有视频流</translation>
    </message>
    <message>
        <source>has no frame %1 (it has %2)</source>
        <translation>没有第 %1 帧（共有 %2 帧）</translation>
    </message>
    <message>
        <source>invalid sample rate %1</source>
        <translation>无效的采样率 %1</translation>
    </message>
    <message>
        <source>the neutral face&apos;s detection kept no tracking seed (thresholds, eyeballs, mouth region) for the classic method</source>
        <translation>中性脸的检测没有保留经典方法所需的跟踪种子（阈值、眼球、嘴巴区域）</translation>
    </message>
    <message>
        <source>%1: no face in any frame</source>
        <translation>%1：没有任何帧含有人脸</translation>
    </message>
    <message>
        <source>the neutral frame is empty</source>
        <translation>中性帧是空的</translation>
    </message>
    <message>
        <source>the %1 tracking cannot follow the face it detected on the neutral frame</source>
        <translation>%1 跟踪无法跟随在中性帧上检测到的人脸</translation>
    </message>
    <message>
        <source>%1: tracking was cancelled</source>
        <translation>%1：跟踪已取消</translation>
    </message>
    <message>
        <source>%1: the neutral frame must be 0 or later</source>
        <translation>%1：中性帧必须为 0 或之后</translation>
    </message>
    <message>
        <source>%1: no video frame could be decoded</source>
        <translation>%1：没有任何帧能够解码</translation>
    </message>
    <message>
        <source>%1: the neutral frame %2 is past the video&apos;s end (it has %3 frames)</source>
        <translation>%1：中性帧 %2 超出视频结尾（视频共有 %3 帧）</translation>
    </message>
    <message>
        <source>%1: frame %2: %3</source>
        <translation>%1：第 %2 帧：%3</translation>
    </message>
    <message>
        <source>%1 (tracked the %2 frames before)</source>
        <translation>%1（已跟踪之前的 %2 帧）</translation>
    </message>
    <message>
        <source>%1: %2 damaged packets were skipped; the frames around them may be wrong</source>
        <translation>%1：跳过了 %2 个损坏的数据包；附近的帧可能有误</translation>
    </message>
    <message>
        <source>%1: the face was lost in %2 of %3 frames (they hold the last pose)</source>
        <translation>%1：%3 帧中有 %2 帧跟丢了人脸（这些帧保留最后的姿势）</translation>
    </message>
    <message>
        <source>%1: the video cannot be decoded (%2)</source>
        <translation>%1：视频无法解码（%2）</translation>
    </message>
    <message>
        <source>%1: cannot convert the video&apos;s pixel format</source>
        <translation>%1：无法转换视频的像素格式</translation>
    </message>
    <message>
        <source>%1: out of memory</source>
        <translation>%1：内存不足</translation>
    </message>
    <message>
        <source>not a video FFmpeg can read (%1)</source>
        <translation>不是 FFmpeg 能读取的视频（%1）</translation>
    </message>
    <message>
        <source>the file holds no video</source>
        <translation>文件中没有视频</translation>
    </message>
    <message>
        <source>cannot set up the video decoder</source>
        <translation>无法配置视频解码器</translation>
    </message>
    <message>
        <source>cannot open the video decoder (%1)</source>
        <translation>无法打开视频解码器（%1）</translation>
    </message>
    <message>
        <source>the video has no picture size</source>
        <translation>视频没有画面尺寸</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>内存不足</translation>
    </message>
    <message>
        <source>the file is cut short or damaged: its data breaks off at %1 s</source>
        <translation>文件不完整或已损坏：数据在 %1 秒处中断</translation>
    </message>
    <message>
        <source>the file is cut short or damaged: %1</source>
        <translation>文件不完整或已损坏：%1</translation>
    </message>
    <message>
        <source>not a readable sound or video file (%1)</source>
        <translation>不是可读取的声音或视频文件（%1）</translation>
    </message>
    <message>
        <source>%1: its sound could not be read (%2): the mouth is not closed in its silences</source>
        <translation>%1：无法读取其声音（%2）：静音处的嘴不会闭上</translation>
    </message>
</context>
<context>
    <name>toonface::VideoView</name>
    <message>
        <source>No video: Animation ▸ Import Video… tracks a clip and shows it here.</source>
        <translation>没有视频：“动画 ▸ 导入视频…”会跟踪片段并在这里显示。</translation>
    </message>
    <message>
        <source>The clip starts at %1 s</source>
        <translation>片段从 %1 秒开始</translation>
    </message>
    <message>
        <source>The clip ended at %1 s</source>
        <translation>片段在 %1 秒结束</translation>
    </message>
    <message>
        <source>frame %1 · %2 s</source>
        <translation>第 %1 帧 · %2 秒</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>第 %1 帧</translation>
    </message>
</context>
<context>
    <name>toonface::WindowLayout</name>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>重置布局(&amp;R)</translation>
    </message>
    <message>
        <source>Put the panels back where they were at first and size them to the window</source>
        <translation>将各面板放回最初的位置，并按窗口调整大小</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>外观</translation>
    </message>
</context>
<context>
    <name>toonface::cli::Cli</name>
    <message>
        <source>The speech recording.</source>
        <translation>语音录音。</translation>
    </message>
    <message>
        <source>The recording&apos;s script (a UTF-8 text file).</source>
        <translation>录音的文稿（UTF-8 文本文件）。</translation>
    </message>
    <message>
        <source>Speak this text with the built-in voice.</source>
        <translation>用内置语音说出这段文字。</translation>
    </message>
    <message>
        <source>Drive the face by a video of the person.</source>
        <translation>用该人物的视频驱动人脸。</translation>
    </message>
    <message>
        <source>Language of the script: cmn or en (default: detected).</source>
        <translation>文稿的语言：cmn 或 en（默认：自动检测）。</translation>
    </message>
    <message>
        <source>Expression while speaking: neutral, smile, sad, angry or surprise.</source>
        <translation>说话时的表情：neutral、smile、sad、angry 或 surprise。</translation>
    </message>
    <message>
        <source>Do not blink.</source>
        <translation>不眨眼。</translation>
    </message>
    <message>
        <source>Frames per second (default 25).</source>
        <translation>每秒帧数（默认 25）。</translation>
    </message>
    <message>
        <source>Drawing style: %1.</source>
        <translation>绘制风格：%1。</translation>
    </message>
    <message>
        <source>Also save the result as a project.</source>
        <translation>同时将结果保存为项目。</translation>
    </message>
    <message>
        <source>A photo or a project; or a video clip, whose neutral frame&apos;s face it animates.</source>
        <translation>照片或项目；或视频片段，以其中性帧的人脸制作动画。</translation>
    </message>
    <message>
        <source>animate takes one photo or project (usage: toonface-cli %1)</source>
        <translation>animate 只接受一张照片或一个项目（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>animate needs exactly one of --audio with --script, --say TEXT or --video CLIP (a project without them plays its own timeline)</source>
        <translation>animate 需要以下其中一项：--audio 配合 --script、--say TEXT 或 --video CLIP（没有这些选项的项目会播放它自己的时间轴）</translation>
    </message>
    <message>
        <source>--audio and --script go together</source>
        <translation>--audio 和 --script 必须一起使用</translation>
    </message>
    <message>
        <source>--fps takes a number from 1 to 120, not &apos;%1&apos;</source>
        <translation>--fps 需要 1 到 120 的数字，而不是“%1”</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (cmn or en)</source>
        <translation>未知的 --lang“%1”（cmn 或 en）</translation>
    </message>
    <message>
        <source>animate takes a photo or a project, not a face JSON (%1)</source>
        <translation>animate 接受照片或项目，不接受人脸 JSON（%1）</translation>
    </message>
    <message>
        <source>%1: cannot write the neutral frame</source>
        <translation>%1：无法写入中性帧</translation>
    </message>
    <message>
        <source>%1: the animation is silent</source>
        <translation>%1：动画没有声音</translation>
    </message>
    <message>
        <source>%1: the clip has no sound; the animation is silent</source>
        <translation>%1：片段没有声音；动画没有声音</translation>
    </message>
    <message>
        <source>animate needs one of --audio with --script, --say TEXT or --video CLIP (only a project plays its own timeline)</source>
        <translation>animate 需要以下其中一项：--audio 配合 --script、--say TEXT 或 --video CLIP（只有项目会播放它自己的时间轴）</translation>
    </message>
    <message>
        <source>%1: the project has no animation to play (its timeline is empty)</source>
        <translation>%1：项目没有可播放的动画（时间轴是空的）</translation>
    </message>
    <message>
        <source>exporting %1 s of animation to %2</source>
        <translation>正在将 %1 秒的动画导出到 %2</translation>
    </message>
    <message>
        <source>The cartoon SVG to write.</source>
        <translation>要写入的卡通 SVG。</translation>
    </message>
    <message>
        <source>Also rasterize to this PNG.</source>
        <translation>同时栅格化为此 PNG。</translation>
    </message>
    <message>
        <source>The PNG&apos;s longer side in pixels (default 512).</source>
        <translation>PNG 的长边像素数（默认 512）。</translation>
    </message>
    <message>
        <source>Expression: neutral, smile, sad, angry or surprise (default: the face as photographed).</source>
        <translation>表情：neutral、smile、sad、angry 或 surprise（默认：照片中的脸）。</translation>
    </message>
    <message>
        <source>Detection method for a photo: auto, classic or landmarks.</source>
        <translation>照片的检测方法：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>How much to exaggerate what makes the face its own: 0 (exact) to 1 (default: the style&apos;s).</source>
        <translation>夸张这张脸独有特征的程度：0（写实）到 1（默认：按风格）。</translation>
    </message>
    <message>
        <source>A photo, a face JSON or a project.</source>
        <translation>照片、人脸 JSON 或项目。</translation>
    </message>
    <message>
        <source>cartoon takes one input (usage: toonface-cli %1)</source>
        <translation>cartoon 只接受一个输入（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>cartoon needs -o OUT.svg</source>
        <translation>cartoon 需要 -o OUT.svg</translation>
    </message>
    <message>
        <source>--size takes a whole number from 16 to 8192, not &apos;%1&apos;</source>
        <translation>--size 需要 16 到 8192 的整数，而不是“%1”</translation>
    </message>
    <message>
        <source>--caricature takes a number from 0 to 1, not &apos;%1&apos;</source>
        <translation>--caricature 需要 0 到 1 的数字，而不是“%1”</translation>
    </message>
    <message>
        <source>Draw the cartoon face of a photo, a face JSON or a project as SVG (and PNG).</source>
        <translation>将照片、人脸 JSON 或项目的卡通脸绘制为 SVG（以及 PNG）。</translation>
    </message>
    <message>
        <source>Detection method: auto, classic or landmarks.</source>
        <translation>检测方法：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>Write the face JSON here (default: stdout).</source>
        <translation>将人脸 JSON 写到这里（默认：标准输出）。</translation>
    </message>
    <message>
        <source>Write intermediate images of the detection here.</source>
        <translation>将检测的中间图像写到这里。</translation>
    </message>
    <message>
        <source>With several faces, use the one at this point of the photo (pixels) instead of the largest, most central one.</source>
        <translation>有多张脸时，使用照片中这个点（像素）处的脸，而不是最大、最居中的那张。</translation>
    </message>
    <message>
        <source>The photo.</source>
        <translation>照片。</translation>
    </message>
    <message>
        <source>detect takes one IMAGE (usage: toonface-cli %1)</source>
        <translation>detect 只接受一个 IMAGE（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>--face wants a point X,Y in photo pixels, not &apos;%1&apos;</source>
        <translation>--face 需要照片像素坐标 X,Y，而不是“%1”</translation>
    </message>
    <message>
        <source>cannot create the debug folder %1</source>
        <translation>无法创建调试文件夹 %1</translation>
    </message>
    <message>
        <source>Find the face in a photo and write its 72 points as JSON (toonface.face/1).</source>
        <translation>在照片中找到人脸，并将其 72 个特征点写成 JSON（toonface.face/1）。</translation>
    </message>
    <message>
        <source>The speech recording (WAV, FLAC, MP3, OGG, M4A or a video&apos;s sound).</source>
        <translation>语音录音（WAV、FLAC、MP3、OGG、M4A 或视频的声音）。</translation>
    </message>
    <message>
        <source>What is said, as UTF-8 text: Chinese characters, pinyin, zhuyin, or English.</source>
        <translation>说了什么，UTF-8 文本：汉字、拼音、注音或英文。</translation>
    </message>
    <message>
        <source>Language of the script: cmn, en, or auto (from the script).</source>
        <translation>文稿的语言：cmn、en 或 auto（根据文稿判断）。</translation>
    </message>
    <message>
        <source>Write the result here: .tsv for Rhubarb-style cues, JSON otherwise (default: JSON on stdout).</source>
        <translation>将结果写到这里：.tsv 为 Rhubarb 格式的提示，其他为 JSON（默认：JSON 输出到标准输出）。</translation>
    </message>
    <message>
        <source>lipsync needs --audio and --script (usage: toonface-cli %1)</source>
        <translation>lipsync 需要 --audio 和 --script（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (cmn, en or auto)</source>
        <translation>未知的 --lang“%1”（cmn、en 或 auto）</translation>
    </message>
    <message>
        <source>aligning %1 with %2</source>
        <translation>正在对齐 %1 和 %2</translation>
    </message>
    <message>
        <source>Time a recording&apos;s syllables against its script and give the mouth shapes (toonface.lipsync/1).</source>
        <translation>将录音的音节与文稿对齐时间，并给出口型（toonface.lipsync/1）。</translation>
    </message>
    <message>
        <source>Language of the text: cmn, en, or auto (from the text).</source>
        <translation>文本的语言：cmn、en 或 auto（根据文本判断）。</translation>
    </message>
    <message>
        <source>The speech: .wav, .flac, .mp3, .ogg, .opus or .m4a.</source>
        <translation>语音：.wav、.flac、.mp3、.ogg、.opus 或 .m4a。</translation>
    </message>
    <message>
        <source>Also write the exact syllable timings and mouth shapes (toonface.lipsync/1).</source>
        <translation>同时写出精确的音节时间和口型（toonface.lipsync/1）。</translation>
    </message>
    <message>
        <source>An espeak-ng voice, optionally with a variant (cmn-latn-pinyin+f2).</source>
        <translation>espeak-ng 语音，可加上变体（cmn-latn-pinyin+f2）。</translation>
    </message>
    <message>
        <source>Words per minute (80-450).</source>
        <translation>每分钟字数（80-450）。</translation>
    </message>
    <message>
        <source>Pitch, 0-100.</source>
        <translation>音高，0-100。</translation>
    </message>
    <message>
        <source>What to say.</source>
        <translation>要说的话。</translation>
    </message>
    <message>
        <source>say takes one TEXT and -o OUT.wav (usage: toonface-cli %1)</source>
        <translation>say 只接受一段 TEXT 和 -o OUT.wav（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>--rate and --pitch take whole numbers</source>
        <translation>--rate 和 --pitch 需要整数</translation>
    </message>
    <message>
        <source>Speak a text with espeak-ng and write the exact syllable timings, so a face can talk without a recording.</source>
        <translation>用 espeak-ng 说出文本并写出精确的音节时间，让脸不需要录音也能说话。</translation>
    </message>
    <message>
        <source>Write the track JSON here (default: stdout).</source>
        <translation>将跟踪 JSON 写到这里（默认：标准输出）。</translation>
    </message>
    <message>
        <source>The video of a speaking face.</source>
        <translation>人脸说话的视频。</translation>
    </message>
    <message>
        <source>track takes one VIDEO (usage: toonface-cli %1)</source>
        <translation>track 只接受一个 VIDEO（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>Track the face of a video frame by frame and write its motion as JSON (toonface.track/1).</source>
        <translation>逐帧跟踪视频中的人脸，并将其动作写成 JSON（toonface.track/1）。</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>显示此帮助。</translation>
    </message>
    <message>
        <source>%1 (usage: %2)</source>
        <translation>%1（用法：%2）</translation>
    </message>
    <message>
        <source>Usage: %1</source>
        <translation>用法：%1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1: not a face JSON: %2 at offset %3</source>
        <translation>%1：不是人脸 JSON：%2，位于偏移 %3</translation>
    </message>
    <message>
        <source>%1: the landmark method could not serve (%2); the points come from the classic method</source>
        <translation>%1：关键点方法无法使用（%2）；特征点来自经典方法</translation>
    </message>
    <message>
        <source>%1: %2 faces found; the largest, most central one is used</source>
        <translation>%1：找到 %2 张脸；使用最大、最居中的那张</translation>
    </message>
    <message>
        <source>unknown --method &apos;%1&apos; (auto, classic or landmarks)</source>
        <translation>未知的 --method“%1”（auto、classic 或 landmarks）</translation>
    </message>
    <message>
        <source>unknown --emotion &apos;%1&apos; (neutral, smile, sad, angry or surprise)</source>
        <translation>未知的 --emotion“%1”（neutral、smile、sad、angry 或 surprise）</translation>
    </message>
    <message>
        <source>unknown --style &apos;%1&apos; (%2)</source>
        <translation>未知的 --style“%1”（%2）</translation>
    </message>
    <message>
        <source>What the drawing shows: head (framed square around the head, the default) or photo (the photo&apos;s whole frame, to lay over the photo).</source>
        <translation>绘图的内容：head（头部周围的方形取景，默认）或 photo（照片的完整画面，可叠加在照片上）。</translation>
    </message>
    <message>
        <source>unknown --frame &apos;%1&apos; (head, photo)</source>
        <translation>未知的 --frame“%1”（head、photo）</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <source>tracking %1: %2 %</source>
        <translation>正在跟踪 %1：%2 %</translation>
    </message>
    <message>
        <source>Toonface turns a photo into a personal cartoon face drawn in SVG and makes it talk.
Every job of the editor, with no display.</source>
        <translation>Toonface 把照片变成以 SVG 绘制的个人卡通脸，并让它说话。
编辑器的每项工作，都不需要显示器。</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>命令：</translation>
    </message>
    <message>
        <source>options of one command</source>
        <translation>单个命令的选项</translation>
    </message>
    <message>
        <source>the version</source>
        <translation>版本</translation>
    </message>
    <message>
        <source>Exit codes: 0 success, 2 usage, 3 unreadable or invalid input, 4 no face found,
5 the audio and the script could not be aligned, 1 other failures.</source>
        <translation>退出代码：0 成功，2 用法错误，3 无法读取或无效的输入，4 找不到人脸，
5 音频与文稿无法对齐，1 其他失败。</translation>
    </message>
    <message>
        <source>no command given; try &apos;toonface-cli --help&apos;</source>
        <translation>未指定命令；请尝试“toonface-cli --help”</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;; try &apos;toonface-cli --help&apos;</source>
        <translation>未知的命令“%1”；请尝试“toonface-cli --help”</translation>
    </message>
    <message>
        <source>%1: interrupted; nothing was written</source>
        <translation>%1：已中断；未写入任何内容</translation>
    </message>
    <message>
        <source>The recording of the whole text, headings included, in reading order.</source>
        <translation>整段文字的录音，包括标题，按阅读顺序。</translation>
    </message>
    <message>
        <source>Read the text with the built-in voice.</source>
        <translation>以内置语音朗读文字。</translation>
    </message>
    <message>
        <source>The face that reads: a photo or a project (default: an average face).</source>
        <translation>朗读的脸：照片或项目（默认：平均脸）。</translation>
    </message>
    <message>
        <source>The book&apos;s language: %1 (default: Chinese or English, as the text reads).</source>
        <translation>书的语言：%1（默认：依文字判断为中文或英文）。</translation>
    </message>
    <message>
        <source>The book&apos;s title (default: its first heading or the file&apos;s name).</source>
        <translation>书名（默认：第一个标题或文件名）。</translation>
    </message>
    <message>
        <source>The book&apos;s author.</source>
        <translation>书的作者。</translation>
    </message>
    <message>
        <source>What reading systems highlight as it is read: sentence or syllable (a character or word).</source>
        <translation>阅读器在朗读时标示的单位：sentence（句子）或 syllable（一个字或单词）。</translation>
    </message>
    <message>
        <source>With --say: words per minute (80-450).</source>
        <translation>配合 --say：每分钟字数（80-450）。</translation>
    </message>
    <message>
        <source>The book.</source>
        <translation>书。</translation>
    </message>
    <message>
        <source>The text: plain UTF-8 (.txt) or Markdown (.md), whose headings make chapters.</source>
        <translation>文字：纯 UTF-8（.txt）或 Markdown（.md），其标题成为章节。</translation>
    </message>
    <message>
        <source>book takes one text file (usage: toonface-cli %1)</source>
        <translation>book 只接受一个文本文件（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>book needs either --audio A (a recording of the text) or --say</source>
        <translation>book 需要 --audio A（文字的录音）或 --say 其中之一</translation>
    </message>
    <message>
        <source>book needs -o BOOK.epub</source>
        <translation>book 需要 -o BOOK.epub</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (%2)</source>
        <translation>未知的 --lang“%1”（%2）</translation>
    </message>
    <message>
        <source>--highlight takes sentence or syllable, not &apos;%1&apos;</source>
        <translation>--highlight 需要 sentence 或 syllable，而不是“%1”</translation>
    </message>
    <message>
        <source>--rate takes a whole number from 80 to 450, not &apos;%1&apos;</source>
        <translation>--rate 需要 80 到 450 的整数，而不是“%1”</translation>
    </message>
    <message>
        <source>%1: %2 %</source>
        <translation>%1：%2 %</translation>
    </message>
    <message>
        <source>%1: %2 chapters, %3 pages, %4 s read aloud</source>
        <translation>%1：%2 章，%3 页，朗读 %4 秒</translation>
    </message>
    <message>
        <source>Make a read-aloud EPUB 3 book of a text: each page a paragraph beside the talking face, its sentences highlighted as the recording or the built-in voice reads them.</source>
        <translation>把文字做成有声的 EPUB 3 书：每页一个段落，旁边是说话的脸，录音或内置语音朗读时逐句标示。</translation>
    </message>
    <message>
        <source>%1 uses files outside its folder: %2</source>
        <translation>%1 使用了其文件夹以外的文件：%2</translation>
    </message>
    <message>
        <source>OUT.svg, OUT.html, OUT.mp4, OUT.gif, OUT.webm, OUT.mov, OUT.apng, OUT.webp, or DIR/ for PNG frames.</source>
        <translation>OUT.svg、OUT.html、OUT.mp4、OUT.gif、OUT.webm、OUT.mov、OUT.apng、OUT.webp，或 PNG 帧的 DIR/。</translation>
    </message>
    <message>
        <source>What is behind the face in a video or picture: a colour (white, #rrggbb), transparent, or a photo (default: transparent for WebM, MOV, APNG, WebP and PNG frames, white for MP4 and GIF).</source>
        <translation>视频或图片中脸后面的东西：颜色（white、#rrggbb）、transparent（透明）或照片（默认：WebM、MOV、APNG、WebP 与 PNG 帧为透明，MP4 与 GIF 为白色）。</translation>
    </message>
    <message>
        <source>Export for a place with limits: %1.</source>
        <translation>为有限制的地方导出：%1。</translation>
    </message>
    <message>
        <source>Video and pictures: begin this many seconds into the animation.</source>
        <translation>视频与图片：从动画的这个秒数开始。</translation>
    </message>
    <message>
        <source>Video and pictures: export this many seconds (default: to the end).</source>
        <translation>视频与图片：导出这么多秒（默认：到结尾）。</translation>
    </message>
    <message>
        <source>animate needs -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|DIR/ ...</source>
        <translation>animate 需要 -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|DIR/ ...</translation>
    </message>
    <message>
        <source>cannot tell the output type of &apos;%1&apos;: use .svg, .html, .mp4, .gif, .webm, .mov, .apng, .webp or a folder ending in /</source>
        <translation>无法判断“%1”的输出类型：请使用 .svg、.html、.mp4、.gif、.webm、.mov、.apng、.webp 或以 / 结尾的文件夹</translation>
    </message>
    <message>
        <source>unknown --preset &apos;%1&apos; (%2)</source>
        <translation>未知的 --preset“%1”（%2）</translation>
    </message>
    <message>
        <source>the %1 preset writes %2: name the output .%3, not &apos;%4&apos;</source>
        <translation>%1 预设会写出 %2：请将输出命名为 .%3，而不是“%4”</translation>
    </message>
    <message>
        <source>--%1 takes a number of seconds (more than 0 for --duration), not &apos;%2&apos;</source>
        <translation>--%1 需要秒数（--duration 需大于 0），而不是“%2”</translation>
    </message>
    <message>
        <source>--%1 needs a video or picture output; SVG and HTML play the whole animation</source>
        <translation>--%1 需要视频或图片输出；SVG 与 HTML 会播放整段动画</translation>
    </message>
    <message>
        <source>%1; nothing was written (--start and --duration choose a stretch)</source>
        <translation>%1；未写入任何内容（--start 与 --duration 可选取一段）</translation>
    </message>
    <message>
        <source>Make the face of a photo or project talk, and export the animation (SVG, HTML, MP4, GIF, WebM, MOV, APNG, WebP or PNG frames).</source>
        <translation>让照片或项目中的脸说话，并导出动画（SVG、HTML、MP4、GIF、WebM、MOV、APNG、WebP 或 PNG 帧）。</translation>
    </message>
    <message>
        <source>exporting</source>
        <translation>正在导出</translation>
    </message>
    <message>
        <source>How the face moves on the pages: svg (an animated drawing) or video (a video of each page read aloud, for reading systems without read-aloud or SVG animation).</source>
        <translation>页面上的脸如何动：svg（动画图）或 video（每一页朗读的视频，供不支持朗读或 SVG 动画的阅读器使用）。</translation>
    </message>
    <message>
        <source>--face-as takes svg or video, not &apos;%1&apos;</source>
        <translation>--face-as 需要 svg 或 video，而不是“%1”</translation>
    </message>
    <message>
        <source>copying the sound</source>
        <translation>正在复制声音</translation>
    </message>
    <message>
        <source>--neutral-frame takes a frame number from 0 or auto, not &apos;%1&apos;</source>
        <translation>--neutral-frame 需要从 0 起算的帧编号或 auto，而不是“%1”</translation>
    </message>
    <message>
        <source>looking for a frame at rest in %1</source>
        <translation>正在 %1 中寻找静止的一帧</translation>
    </message>
    <message>
        <source>%1: neutral frame %2 (mouth closed, eyes open, in a silence; --neutral-frame N names another)</source>
        <translation>%1：中性帧为第 %2 帧（嘴闭着、眼睁开、无人说话；用 --neutral-frame N 指定其他帧）</translation>
    </message>
    <message>
        <source>%1: neutral frame %2 (mouth closed, eyes open; --neutral-frame N names another)</source>
        <translation>%1：中性帧为第 %2 帧（嘴闭着、眼睁开；用 --neutral-frame N 指定其他帧）</translation>
    </message>
</context>
</TS>
