<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>DetectionSteps</name>
    <message>
        <source>B1 – dark regions (1st level, intensity)</source>
        <translation>B1 – 暗部區域（第一層，亮度）</translation>
    </message>
    <message>
        <source>B2 – face regions (2nd level, hue)</source>
        <translation>B2 – 臉部區域（第二層，色相）</translation>
    </message>
    <message>
        <source>B3 – B1 and B2 (for the hair region)</source>
        <translation>B3 – B1 與 B2（用於頭髮區域）</translation>
    </message>
    <message>
        <source>Face and hair regions</source>
        <translation>臉部與頭髮區域</translation>
    </message>
    <message>
        <source>Eye-pair candidates and the chosen pair</source>
        <translation>雙眼候選與選定的一對</translation>
    </message>
    <message>
        <source>Eyeballs and the 2d square</source>
        <translation>眼球與 2d 正方形</translation>
    </message>
    <message>
        <source>Edges and division lines</source>
        <translation>邊緣與分割線</translation>
    </message>
    <message>
        <source>Feature regions</source>
        <translation>五官區域</translation>
    </message>
    <message>
        <source>Feature points (thesis pipeline)</source>
        <translation>特徵點（論文流程）</translation>
    </message>
    <message>
        <source>Landmarks</source>
        <translation>關鍵點</translation>
    </message>
    <message>
        <source>Hair region</source>
        <translation>頭髮區域</translation>
    </message>
    <message>
        <source>Points, close-up</source>
        <translation>特徵點特寫</translation>
    </message>
    <message>
        <source>thesis pipeline</source>
        <translation>論文流程</translation>
    </message>
    <message>
        <source>%1, close-up</source>
        <translation>%1，特寫</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>MovePointCommand</name>
    <message>
        <source>Move point %1</source>
        <translation>移動特徵點 %1</translation>
    </message>
</context>
<context>
    <name>PointHandle</name>
    <message>
        <source>hair</source>
        <translation>頭髮</translation>
    </message>
    <message>
        <source>face contour</source>
        <translation>臉部輪廓</translation>
    </message>
    <message>
        <source>ears</source>
        <translation>耳朵</translation>
    </message>
    <message>
        <source>eyebrows</source>
        <translation>眉毛</translation>
    </message>
    <message>
        <source>eyes</source>
        <translation>眼睛</translation>
    </message>
    <message>
        <source>nose</source>
        <translation>鼻子</translation>
    </message>
    <message>
        <source>mouth</source>
        <translation>嘴巴</translation>
    </message>
    <message>
        <source>Point %1 (%2)</source>
        <translation>特徵點 %1（%2）</translation>
    </message>
    <message>
        <source>Control point: animation moves it</source>
        <translation>控制點：動畫會移動它</translation>
    </message>
    <message>
        <source>Placed by hand: re-detection keeps it</source>
        <translation>手動放置：重新偵測時保留</translation>
    </message>
</context>
<context>
    <name>PoseKeyDrag</name>
    <message>
        <source>Left brow, outer</source>
        <translation>左眉，外側</translation>
    </message>
    <message>
        <source>Left brow, outer middle</source>
        <translation>左眉，外側中段</translation>
    </message>
    <message>
        <source>Left brow, inner middle</source>
        <translation>左眉，內側中段</translation>
    </message>
    <message>
        <source>Left brow, inner</source>
        <translation>左眉，內側</translation>
    </message>
    <message>
        <source>Right brow, inner</source>
        <translation>右眉，內側</translation>
    </message>
    <message>
        <source>Right brow, inner middle</source>
        <translation>右眉，內側中段</translation>
    </message>
    <message>
        <source>Right brow, outer middle</source>
        <translation>右眉，外側中段</translation>
    </message>
    <message>
        <source>Right brow, outer</source>
        <translation>右眉，外側</translation>
    </message>
    <message>
        <source>Left upper lid</source>
        <translation>左上眼瞼</translation>
    </message>
    <message>
        <source>Left lower lid</source>
        <translation>左下眼瞼</translation>
    </message>
    <message>
        <source>Right upper lid</source>
        <translation>右上眼瞼</translation>
    </message>
    <message>
        <source>Right lower lid</source>
        <translation>右下眼瞼</translation>
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
        <translation>下顎（帶動下唇與下巴）</translation>
    </message>
    <message>
        <source>Set Pose Key</source>
        <translation>設定姿勢關鍵影格</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>No sound</source>
        <translation>無聲音</translation>
    </message>
</context>
<context>
    <name>TimelineLayout</name>
    <message>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <source>Audio</source>
        <translation>音訊</translation>
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
        <translation>頭部</translation>
    </message>
    <message>
        <source>Gaze</source>
        <translation>視線</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>姿勢</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Toonface: personal cartoon faces from photos.</source>
        <translation>Toonface：用照片做出個人卡通臉。</translation>
    </message>
    <message>
        <source>A photo or a .toonface project to open.</source>
        <translation>要開啟的照片或 .toonface 專案。</translation>
    </message>
    <message>
        <source>Detect faces with METHOD in this session: auto, classic or landmarks.</source>
        <translation>本次工作階段以 METHOD 偵測臉部：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>unknown detection method &quot;%1&quot; (auto, classic or landmarks)</source>
        <translation>不明的偵測方法「%1」（auto、classic 或 landmarks）</translation>
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
        <translation>%1：不是可讀取的影像</translation>
    </message>
</context>
<context>
    <name>toonface::AppearancePanel</name>
    <message>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <source>Skin</source>
        <translation>皮膚</translation>
    </message>
    <message>
        <source>Hair</source>
        <translation>頭髮</translation>
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
        <translation>臉頰</translation>
    </message>
    <message>
        <source>Glasses</source>
        <translation>眼鏡</translation>
    </message>
    <message>
        <source>Moustache</source>
        <translation>八字鬍</translation>
    </message>
    <message>
        <source>Beard</source>
        <translation>鬍鬚</translation>
    </message>
    <message>
        <source>Hat</source>
        <translation>帽子</translation>
    </message>
    <message>
        <source>Drawing</source>
        <translation>繪製</translation>
    </message>
    <message>
        <source>Cute proportions</source>
        <translation>可愛比例</translation>
    </message>
    <message>
        <source>How much the drawing exaggerates what makes this face its own (0 = exact)</source>
        <translation>繪圖誇張這張臉獨有特徵的程度（0 = 寫實）</translation>
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
        <translation>誇張程度：</translation>
    </message>
    <message>
        <source>Worn and grown</source>
        <translation>配戴與毛髮</translation>
    </message>
    <message>
        <source>Bald head</source>
        <translation>光頭</translation>
    </message>
    <message>
        <source>Glasses:</source>
        <translation>眼鏡：</translation>
    </message>
    <message>
        <source>Resample colours from the photo</source>
        <translation>從照片重新取色</translation>
    </message>
    <message>
        <source>Skin, hair, eyes and lips from the photo (its colour cast taken out), and what the person wears</source>
        <translation>從照片取得皮膚、頭髮、眼睛和嘴唇的顏色（去除色偏），以及人物的穿戴</translation>
    </message>
    <message>
        <source>Eyebrows</source>
        <translation>眉毛</translation>
    </message>
    <message>
        <source>Cute</source>
        <translation>可愛</translation>
    </message>
    <message>
        <source>Caricature</source>
        <translation>誇張程度</translation>
    </message>
    <message>
        <source>Resample colours</source>
        <translation>重新取色</translation>
    </message>
    <message>
        <source>Colours and lines</source>
        <translation>顏色與線條</translation>
    </message>
    <message>
        <source>Shown</source>
        <translation>顯示</translation>
    </message>
    <message>
        <source>Fill</source>
        <translation>填色</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>線條</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>粗細</translation>
    </message>
    <message>
        <source>Line weight in hundredths of the eye distance</source>
        <translation>線條粗細，以雙眼距離的百分之一為單位</translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation>顯示%1</translation>
    </message>
    <message>
        <source>Line weight</source>
        <translation>線條粗細</translation>
    </message>
    <message>
        <source>Line colour</source>
        <translation>線條顏色</translation>
    </message>
    <message>
        <source>Fill colour</source>
        <translation>填色顏色</translation>
    </message>
    <message>
        <source>Neck and shoulders</source>
        <translation>脖子與肩膀</translation>
    </message>
    <message>
        <source>Expression lines</source>
        <translation>表情紋</translation>
    </message>
    <message>
        <source>Smile blush</source>
        <translation>微笑腮紅</translation>
    </message>
    <message>
        <source>Your layers</source>
        <translation>你的圖層</translation>
    </message>
</context>
<context>
    <name>toonface::ApplyDetection</name>
    <message>
        <source>Use another face</source>
        <translation>使用另一張臉</translation>
    </message>
    <message>
        <source>Detect face</source>
        <translation>偵測臉部</translation>
    </message>
    <message>
        <source>Sample colours</source>
        <translation>取樣顏色</translation>
    </message>
    <message>
        <source>Re-detect keeping my points</source>
        <translation>重新偵測並保留我的特徵點</translation>
    </message>
    <message>
        <source>Re-detect points</source>
        <translation>重新偵測特徵點</translation>
    </message>
    <message>
        <source>Face found by the %1 method in %2 ms.</source>
        <translation>以 %1 方法找到臉部，耗時 %2 毫秒。</translation>
    </message>
    <message numerus="yes">
        <source>%n faces found: using the one you chose (%1, %2 ms).</source>
        <translation>
            <numerusform>找到 %n 張臉：使用您選擇的那張（%1，%2 毫秒）。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n faces found: using the largest, most central one (%1, %2 ms). Click another face&apos;s box to switch.</source>
        <translation>
            <numerusform>找到 %n 張臉：使用最大、最靠中央的那張（%1，%2 毫秒）。按一下其他臉的方框即可切換。</numerusform>
        </translation>
    </message>
    <message>
        <source>The landmark method could not serve: %1</source>
        <translation>關鍵點方法無法使用：%1</translation>
    </message>
</context>
<context>
    <name>toonface::Autosaver</name>
    <message>
        <source>%1: cannot write the recovery file: %2</source>
        <translation>%1：無法寫入復原檔案：%2</translation>
    </message>
    <message>
        <source>%1: cannot write the recovery file</source>
        <translation>%1：無法寫入復原檔案</translation>
    </message>
</context>
<context>
    <name>toonface::BlinksDialog</name>
    <message>
        <source>&amp;From</source>
        <translation>從(&amp;F)</translation>
    </message>
    <message>
        <source>Add Blinks</source>
        <translation>加入眨眼</translation>
    </message>
    <message>
        <source>Blinks at a person&apos;s pace: about one every three and a half seconds, now and then two in a row. The same seed always gives the same blinks.</source>
        <translation>依真人的節奏眨眼：大約每三秒半一次，偶爾連眨兩下。相同的種子永遠產生相同的眨眼。</translation>
    </message>
    <message>
        <source>&amp;New Seed</source>
        <translation>新種子(&amp;N)</translation>
    </message>
    <message>
        <source>The &amp;whole animation (%1 s)</source>
        <translation>整段動畫（%1 秒）(&amp;W)</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source>&amp;Seed:</source>
        <translation>種子(&amp;S)：</translation>
    </message>
    <message>
        <source>Over:</source>
        <translation>範圍：</translation>
    </message>
    <message>
        <source>The range ends before it starts.</source>
        <translation>範圍的結束早於開始。</translation>
    </message>
    <message numerus="yes">
        <source>%n blink(s) from %1 s to %2 s.</source>
        <translation>
            <numerusform>從 %1 秒到 %2 秒共 %n 次眨眼。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The %n blink(s) there now are replaced.</source>
        <translation>
            <numerusform>此範圍原有的 %n 次眨眼會被取代。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::CameraFeed</name>
    <message>
        <source>No camera was found on this computer. Connect a camera and try again, or open a photo (File ▸ Open) or a video instead.</source>
        <translation>這台電腦上找不到攝影機。請連接攝影機後再試一次，或改為開啟照片（檔案 ▸ 開啟）或影片。</translation>
    </message>
    <message>
        <source>The camera “%1” stopped: %2</source>
        <translation>攝影機「%1」已停止：%2</translation>
    </message>
    <message>
        <source>The camera “%1” was disconnected.</source>
        <translation>攝影機「%1」已中斷連線。</translation>
    </message>
</context>
<context>
    <name>toonface::CaptureDialog</name>
    <message>
        <source>&amp;Take Photo in 3 s</source>
        <translation>3 秒後拍照(&amp;T)</translation>
    </message>
    <message>
        <source>Capture from Camera</source>
        <translation>從攝影機擷取</translation>
    </message>
    <message>
        <source>Look straight at the camera with a relaxed face, mouth closed: the photo becomes the neutral face</source>
        <translation>放鬆臉部、閉上嘴巴，直視攝影機：這張照片會成為中性臉</translation>
    </message>
    <message>
        <source>&amp;Camera:</source>
        <translation>攝影機(&amp;C)：</translation>
    </message>
    <message>
        <source>No camera</source>
        <translation>沒有攝影機</translation>
    </message>
    <message>
        <source>No face in view yet.</source>
        <translation>畫面中還沒有臉。</translation>
    </message>
    <message>
        <source>Face found: keep still and take the photo.</source>
        <translation>找到臉部：請保持不動並拍照。</translation>
    </message>
    <message>
        <source>Starting the camera…</source>
        <translation>正在啟動攝影機…</translation>
    </message>
    <message>
        <source>Camera “%1”</source>
        <translation>攝影機「%1」</translation>
    </message>
    <message>
        <source>The camera has not shown a picture yet.</source>
        <translation>攝影機尚未顯示任何畫面。</translation>
    </message>
    <message>
        <source>%1: the photo cannot be written</source>
        <translation>%1：無法寫入照片</translation>
    </message>
</context>
<context>
    <name>toonface::CartoonFile</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1：無法寫入：%2</translation>
    </message>
    <message>
        <source>%1: no image format: give the file a suffix (.svg, .png)</source>
        <translation>%1：沒有影像格式：請為檔案加上副檔名（.svg、.png）</translation>
    </message>
    <message>
        <source>%1: the cartoon could not be drawn</source>
        <translation>%1：無法繪製卡通</translation>
    </message>
    <message>
        <source>%1: cannot encode the image as %2</source>
        <translation>%1：無法將影像編碼為 %2</translation>
    </message>
</context>
<context>
    <name>toonface::DetectionStepsUi</name>
    <message>
        <source>Detection &amp;Steps</source>
        <translation>偵測步驟(&amp;S)</translation>
    </message>
    <message>
        <source>Detection Steps</source>
        <translation>偵測步驟</translation>
    </message>
    <message>
        <source>Step:</source>
        <translation>步驟：</translation>
    </message>
    <message>
        <source>Opacity:</source>
        <translation>不透明度：</translation>
    </message>
    <message>
        <source>How strongly the detection step covers the photo</source>
        <translation>偵測步驟覆蓋照片的濃淡程度</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>無(&amp;N)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>無</translation>
    </message>
    <message>
        <source>Draw “%1” over the photo (%2.png with --debug-dir)</source>
        <translation>在照片上繪製「%1」（使用 --debug-dir 時為 %2.png）</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Show “%1” in a window of its own (%2.png with --debug-dir)</source>
        <translation>在獨立視窗中顯示「%1」（使用 --debug-dir 時為 %2.png）</translation>
    </message>
    <message>
        <source>Show an intermediate image of the face detection over the photo</source>
        <translation>在照片上顯示臉部偵測的中間影像</translation>
    </message>
</context>
<context>
    <name>toonface::Detector</name>
    <message>
        <source>No face was found in the image (%1 x %2 pixels). A frontal, upright face at least %3 pixels wide is needed.</source>
        <translation>在影像（%1 x %2 像素）中找不到臉。需要一張正面、端正且至少 %3 像素寬的臉。</translation>
    </message>
    <message>
        <source>The image (%1 x %2 pixels) is too small to hold a face.</source>
        <translation>影像（%1 x %2 像素）太小，容不下一張臉。</translation>
    </message>
</context>
<context>
    <name>toonface::Document</name>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
</context>
<context>
    <name>toonface::EmotionDialog</name>
    <message>
        <source>The emotions already there &amp;give way</source>
        <translation>讓已有的表情退讓(&amp;G)</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>加入表情</translation>
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
        <translation>否則新表情會疊加在下方的表情上</translation>
    </message>
    <message>
        <source>&amp;Emotion:</source>
        <translation>表情(&amp;E)：</translation>
    </message>
    <message>
        <source>&amp;From:</source>
        <translation>從(&amp;F)：</translation>
    </message>
    <message>
        <source>&amp;Intensity:</source>
        <translation>強度(&amp;I)：</translation>
    </message>
    <message>
        <source>Fade:</source>
        <translation>淡入淡出：</translation>
    </message>
    <message>
        <source>Add Emotion (%1)</source>
        <translation>加入表情（%1）</translation>
    </message>
</context>
<context>
    <name>toonface::EmotionPalette</name>
    <message>
        <source>%1: click to apply to the selection (or 2 s from the playhead), or drag onto the emotion track</source>
        <translation>%1：按一下套用到所選範圍（或從播放頭起 2 秒），或拖曳到表情軌</translation>
    </message>
</context>
<context>
    <name>toonface::ExportAnimationDialog</name>
    <message>
        <source>SVG animation (SMIL)</source>
        <translation>SVG 動畫（SMIL）</translation>
    </message>
    <message>
        <source>HTML player</source>
        <translation>HTML 播放器</translation>
    </message>
    <message>
        <source>MP4 video</source>
        <translation>MP4 影片</translation>
    </message>
    <message>
        <source>Animated GIF</source>
        <translation>GIF 動畫</translation>
    </message>
    <message>
        <source>PNG sequence (a folder of frames)</source>
        <translation>PNG 序列（一個放影格的資料夾）</translation>
    </message>
    <message>
        <source>SVG animation (*.svg)</source>
        <translation>SVG 動畫 (*.svg)</translation>
    </message>
    <message>
        <source>HTML page (*.html *.htm)</source>
        <translation>HTML 網頁 (*.html *.htm)</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4)</source>
        <translation>MP4 影片 (*.mp4)</translation>
    </message>
    <message>
        <source>Animated GIF (*.gif)</source>
        <translation>GIF 動畫 (*.gif)</translation>
    </message>
    <message>
        <source>Folder for the frames (*)</source>
        <translation>影格資料夾 (*)</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation>匯出動畫</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <source>Choose where to save the animation</source>
        <translation>選擇動畫的儲存位置</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自動</translation>
    </message>
    <message>
        <source>%1 px</source>
        <translation>%1 像素</translation>
    </message>
    <message>
        <source>The longer side of the video frames; the drawing is vector, so any size is sharp</source>
        <translation>影片畫面的長邊；繪圖是向量圖，任何尺寸都清晰</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>The head</source>
        <translation>頭部</translation>
    </message>
    <message>
        <source>The whole photo</source>
        <translation>整張照片</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>格式(&amp;F)：</translation>
    </message>
    <message>
        <source>&amp;Save to:</source>
        <translation>儲存到(&amp;S)：</translation>
    </message>
    <message>
        <source>Frame si&amp;ze:</source>
        <translation>畫面大小(&amp;Z)：</translation>
    </message>
    <message>
        <source>Frame &amp;rate:</source>
        <translation>影格速率(&amp;R)：</translation>
    </message>
    <message>
        <source>Fr&amp;aming:</source>
        <translation>取景(&amp;A)：</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>匯出(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Show in Folder</source>
        <translation>在資料夾中顯示(&amp;S)</translation>
    </message>
    <message>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 已存在。要取代嗎？</translation>
    </message>
    <message>
        <source>Exporting to %1…</source>
        <translation>正在匯出到 %1…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 個影格</numerusform>
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
        <translation>向量圖</translation>
    </message>
    <message>
        <source>silent</source>
        <translation>無聲</translation>
    </message>
    <message>
        <source>with sound</source>
        <translation>有聲音</translation>
    </message>
    <message>
        <source>no sound</source>
        <translation>無聲音</translation>
    </message>
    <message>
        <source>%1: the export stopped</source>
        <translation>%1：匯出已停止</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>已匯出到 %1。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>已取消：沒有寫入任何檔案。</translation>
    </message>
    <message>
        <source>Not exported: %1</source>
        <translation>未匯出：%1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
</context>
<context>
    <name>toonface::FrameDecoder</name>
    <message>
        <source>%1: has no frame %2 (it has %3)</source>
        <translation>%1：沒有第 %2 個影格（只有 %3 個）</translation>
    </message>
</context>
<context>
    <name>toonface::ImportVideoDialog</name>
    <message>
        <source>Snap to the nine mouth &amp;shapes (mouth keys)</source>
        <translation>對齊九種口型(&amp;S)（口型關鍵影格）</translation>
    </message>
    <message>
        <source>Keep the &amp;continuous motion (pose keys)</source>
        <translation>保留連續動作(&amp;C)（姿勢關鍵影格）</translation>
    </message>
    <message>
        <source>Use the clip&apos;s s&amp;ound as the project&apos;s sound</source>
        <translation>使用片段的聲音作為專案的聲音(&amp;O)</translation>
    </message>
    <message>
        <source>At the &amp;playhead (%1)</source>
        <translation>在播放頭處（%1）(&amp;P)</translation>
    </message>
    <message>
        <source>At the s&amp;tart (0 s)</source>
        <translation>從開頭（0 秒）(&amp;T)</translation>
    </message>
    <message>
        <source>Use the neutral frame as the p&amp;hoto (a new project with its face)</source>
        <translation>使用中性影格作為照片(&amp;H)（以其臉部建立新專案）</translation>
    </message>
    <message>
        <source>Import Video</source>
        <translation>匯入影片</translation>
    </message>
    <message>
        <source>Tracks a clip of a person speaking: the face of the neutral frame is the rest pose, and the motion of every other frame lands on the timeline as key frames (pose, blinks, gaze, head), editable like any others.</source>
        <translation>追蹤一段人物說話的片段：中性影格的臉是靜止姿勢，其他每個影格的動作都會以關鍵影格（姿勢、眨眼、視線、頭部）放到時間軸上，可像其他關鍵影格一樣編輯。</translation>
    </message>
    <message>
        <source>A video of a face speaking</source>
        <translation>一段臉部說話的影片</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <source>Choose a clip</source>
        <translation>選擇片段</translation>
    </message>
    <message>
        <source>The frame whose face is at rest: mouth closed, eyes open, looking ahead</source>
        <translation>臉部處於靜止狀態的影格：閉嘴、睜眼、直視前方</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自動</translation>
    </message>
    <message>
        <source>Landmarks</source>
        <translation>關鍵點</translation>
    </message>
    <message>
        <source>Classic (thesis ch. 6)</source>
        <translation>經典（論文第 6 章）</translation>
    </message>
    <message>
        <source>The project has no face yet: the neutral frame becomes its photo, saved as a PNG beside the clip</source>
        <translation>專案還沒有臉：中性影格會成為它的照片，以 PNG 儲存在片段旁</translation>
    </message>
    <message>
        <source>&amp;Clip:</source>
        <translation>片段(&amp;C)：</translation>
    </message>
    <message>
        <source>&amp;Neutral frame:</source>
        <translation>中性影格(&amp;N)：</translation>
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
        <translation>聲音：</translation>
    </message>
    <message>
        <source>Starts:</source>
        <translation>開始於：</translation>
    </message>
    <message>
        <source>Photo:</source>
        <translation>照片：</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>匯入(&amp;I)</translation>
    </message>
    <message>
        <source>Tracking frame %1 of %2</source>
        <translation>正在追蹤第 %1 個影格，共 %2 個</translation>
    </message>
    <message>
        <source>Tracking frame %1</source>
        <translation>正在追蹤第 %1 個影格</translation>
    </message>
    <message>
        <source>No picture</source>
        <translation>沒有畫面</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 個影格</numerusform>
        </translation>
    </message>
    <message>
        <source>frames not counted</source>
        <translation>未計算影格數</translation>
    </message>
    <message>
        <source>%1 × %2, %3 at %4 fps, %5, %6</source>
        <translation>%1 × %2，%3，%4 fps，%5，%6</translation>
    </message>
    <message>
        <source>with sound</source>
        <translation>有聲音</translation>
    </message>
    <message>
        <source>no sound</source>
        <translation>無聲音</translation>
    </message>
    <message>
        <source>Decoding…</source>
        <translation>正在解碼…</translation>
    </message>
    <message>
        <source>Video (*.mp4 *.mov *.mkv *.webm *.avi *.mpg *.mpeg *.m4v *.gif);;All files (*)</source>
        <translation>影片 (*.mp4 *.mov *.mkv *.webm *.avi *.mpg *.mpeg *.m4v *.gif);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>第 %1 個影格</translation>
    </message>
    <message>
        <source>Finding the face on frame %1</source>
        <translation>正在第 %1 個影格上尋找臉部</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Nothing was changed.</source>
        <translation>沒有任何變更。</translation>
    </message>
    <message>
        <source>Cancelled: nothing was changed.</source>
        <translation>已取消：沒有任何變更。</translation>
    </message>
    <message>
        <source>%1: no frame could be tracked</source>
        <translation>%1：沒有任何影格能追蹤</translation>
    </message>
    <message>
        <source>%1: cannot write the neutral frame there</source>
        <translation>%1：無法在該處寫入中性影格</translation>
    </message>
    <message>
        <source>Import Video %1</source>
        <translation>匯入影片 %1</translation>
    </message>
</context>
<context>
    <name>toonface::LanguageBox</name>
    <message>
        <source>Detect from the script</source>
        <translation>依文稿自動判斷</translation>
    </message>
    <message>
        <source>Mandarin (普通话)</source>
        <translation>華語（普通話）</translation>
    </message>
    <message>
        <source>English</source>
        <translation>英語</translation>
    </message>
</context>
<context>
    <name>toonface::LayersEditor</name>
    <message>
        <source>Your own SVG drawings over or under the face, in drawing order; untick to hide</source>
        <translation>你自己的 SVG 圖畫，畫在臉的前面或後面，依繪製順序排列；取消勾選即隱藏</translation>
    </message>
    <message>
        <source>Add…</source>
        <translation>加入…</translation>
    </message>
    <message>
        <source>Add a drawing from an SVG file (clothing, an accessory); the project keeps a copy</source>
        <translation>從 SVG 檔案加入圖畫（衣服、配件）；專案會保存一份副本</translation>
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
        <translation>較早繪製（更靠後）</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <source>Draw later (further forward)</source>
        <translation>較晚繪製（更靠前）</translation>
    </message>
    <message>
        <source>Across from the face&apos;s centre, in eye distances (right is positive)</source>
        <translation>從臉部中心水平偏移，以雙眼距離為單位（向右為正）</translation>
    </message>
    <message>
        <source>Down from the face&apos;s centre, in eye distances</source>
        <translation>從臉部中心向下偏移，以雙眼距離為單位</translation>
    </message>
    <message>
        <source>The drawing&apos;s width, in eye distances</source>
        <translation>圖畫的寬度，以雙眼距離為單位</translation>
    </message>
    <message>
        <source>In front of the face</source>
        <translation>在臉的前面</translation>
    </message>
    <message>
        <source>Unticked, the drawing lies behind the head, over the neck and shoulders</source>
        <translation>取消勾選時，圖畫位於頭部後面、脖子與肩膀之上</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>寬度：</translation>
    </message>
    <message>
        <source>Remove layer</source>
        <translation>移除圖層</translation>
    </message>
    <message>
        <source>Show layer</source>
        <translation>顯示圖層</translation>
    </message>
    <message>
        <source>Hide layer</source>
        <translation>隱藏圖層</translation>
    </message>
    <message>
        <source>Move layer</source>
        <translation>移動圖層</translation>
    </message>
    <message>
        <source>Resize layer</source>
        <translation>調整圖層大小</translation>
    </message>
    <message>
        <source>Layer in front</source>
        <translation>圖層移到前面</translation>
    </message>
    <message>
        <source>Layer behind</source>
        <translation>圖層移到後面</translation>
    </message>
    <message>
        <source>There is no face to place %1 on.</source>
        <translation>沒有可以放置 %1 的臉。</translation>
    </message>
    <message>
        <source>Add layer %1</source>
        <translation>加入圖層 %1</translation>
    </message>
    <message>
        <source>Add layers</source>
        <translation>加入圖層</translation>
    </message>
    <message>
        <source>SVG drawings (*.svg);;All files (*)</source>
        <translation>SVG 圖畫 (*.svg);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Add layer</source>
        <translation>加入圖層</translation>
    </message>
    <message>
        <source>Reorder layers</source>
        <translation>重新排列圖層</translation>
    </message>
    <message>
        <source>%1 (behind)</source>
        <translation>%1（後面）</translation>
    </message>
    <message>
        <source>Moves with the head</source>
        <translation>隨頭部移動</translation>
    </message>
    <message>
        <source>Ticked, the drawing moves, turns and nods with the head (a hat, glasses, earrings); unticked, it stays still as the head moves (clothes)</source>
        <translation>勾選時，圖畫隨頭部移動、轉動和點頭（帽子、眼鏡、耳環）；不勾選時，頭部移動時它保持不動（衣服）</translation>
    </message>
    <message>
        <source>Layer follows the head</source>
        <translation>圖層隨頭部移動</translation>
    </message>
    <message>
        <source>Layer stays still</source>
        <translation>圖層保持不動</translation>
    </message>
</context>
<context>
    <name>toonface::LipSyncDialog</name>
    <message>
        <source>Lip Sync</source>
        <translation>唇形同步</translation>
    </message>
    <message>
        <source>Lip Sync from Recording</source>
        <translation>依錄音做唇形同步</translation>
    </message>
    <message>
        <source>Aligns a recording with the script it speaks, syllable by syllable. The mouth keys and the script&apos;s syllables where the recording plays are replaced; the rest of the timeline is kept.</source>
        <translation>將錄音與其朗讀的文稿逐音節對齊。錄音播放範圍內的口型關鍵影格與文稿音節會被取代，時間軸的其餘部分保持不變。</translation>
    </message>
    <message>
        <source>An audio file, or a video whose sound is used</source>
        <translation>音訊檔案，或使用其聲音的影片</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <source>Where the recording starts on the timeline</source>
        <translation>錄音在時間軸上的開始位置</translation>
    </message>
    <message>
        <source>Type the words spoken in the recording (Chinese characters, pinyin, Zhuyin or English), or open a text file.</source>
        <translation>輸入錄音中說的話（漢字、拼音、注音或英文），或開啟文字檔。</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>開啟…</translation>
    </message>
    <message>
        <source>&amp;Recording:</source>
        <translation>錄音(&amp;R)：</translation>
    </message>
    <message>
        <source>&amp;Starts at:</source>
        <translation>開始於(&amp;S)：</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
    <message>
        <source>S&amp;cript:</source>
        <translation>文稿(&amp;C)：</translation>
    </message>
    <message>
        <source>%1: cannot be read (%2)</source>
        <translation>%1：無法讀取（%2）</translation>
    </message>
    <message>
        <source>%1: not a UTF-8 text file</source>
        <translation>%1：不是 UTF-8 文字檔</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>錄音</translation>
    </message>
    <message>
        <source>Sound and video (*.wav *.flac *.mp3 *.ogg *.opus *.m4a *.aac *.mp4 *.mov *.mkv *.webm *.avi);;All files (*)</source>
        <translation>聲音與影片 (*.wav *.flac *.mp3 *.ogg *.opus *.m4a *.aac *.mp4 *.mov *.mkv *.webm *.avi);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>文稿</translation>
    </message>
    <message>
        <source>Text (*.txt);;All files (*)</source>
        <translation>文字 (*.txt);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Type or open the script the recording speaks.</source>
        <translation>輸入或開啟錄音所朗讀的文稿。</translation>
    </message>
    <message>
        <source>Loading the character dictionary…</source>
        <translation>正在載入字典…</translation>
    </message>
    <message numerus="yes">
        <source>%n word(s) in English</source>
        <translation>
            <numerusform>%n 個英文單字</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n syllable(s) in Mandarin</source>
        <translation>
            <numerusform>%n 個華語音節</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading %1</source>
        <translation>正在讀取 %1</translation>
    </message>
    <message>
        <source>the script</source>
        <translation>文稿</translation>
    </message>
    <message>
        <source>Lip Sync from %1</source>
        <translation>依 %1 做唇形同步</translation>
    </message>
</context>
<context>
    <name>toonface::LiveSession</name>
    <message>
        <source>Rest pose set (tracking by %1)</source>
        <translation>已設定靜止姿勢（以 %1 追蹤）</translation>
    </message>
    <message>
        <source>No face for the rest pose: %1</source>
        <translation>沒有可作為靜止姿勢的臉：%1</translation>
    </message>
</context>
<context>
    <name>toonface::LiveTakeText</name>
    <message>
        <source>Nothing was recorded: no frame with a face was tracked.</source>
        <translation>沒有錄到任何內容：沒有追蹤到任何有臉的影格。</translation>
    </message>
    <message>
        <source>%1: cannot create its folder</source>
        <translation>%1：無法建立其資料夾</translation>
    </message>
    <message>
        <source>Record Live Take</source>
        <translation>錄製即時演出</translation>
    </message>
    <message>
        <source>Recorded %1 s (%2 frames) with its sound, saved as %3</source>
        <translation>已錄製 %1 秒（%2 個影格）並含聲音，儲存為 %3</translation>
    </message>
    <message>
        <source>Recorded %1 s (%2 frames): motion only, no sound</source>
        <translation>已錄製 %1 秒（%2 個影格）：只有動作，沒有聲音</translation>
    </message>
</context>
<context>
    <name>toonface::LiveWindow</name>
    <message>
        <source>&amp;Loop clip</source>
        <translation>循環播放片段(&amp;L)</translation>
    </message>
    <message>
        <source>Set &amp;Rest Pose</source>
        <translation>設定靜止姿勢(&amp;R)</translation>
    </message>
    <message>
        <source>● &amp;Record</source>
        <translation>● 錄製(&amp;R)</translation>
    </message>
    <message>
        <source>Live Mode — Toonface</source>
        <translation>即時模式 — Toonface</translation>
    </message>
    <message>
        <source>Mouth from camera</source>
        <translation>嘴巴跟隨攝影機</translation>
    </message>
    <message>
        <source>Mouth from microphone</source>
        <translation>嘴巴跟隨麥克風</translation>
    </message>
    <message>
        <source>Camera, microphone when lips are lost</source>
        <translation>攝影機，嘴唇跟丟時用麥克風</translation>
    </message>
    <message>
        <source>What drives the cartoon&apos;s mouth: the lips the camera sees, the loudness and colour of the voice, or both</source>
        <translation>驅動卡通嘴巴的來源：攝影機看到的嘴唇、聲音的大小與音色，或兩者並用</translation>
    </message>
    <message>
        <source>Take the current frame as the performer&apos;s neutral face</source>
        <translation>將目前的影格作為表演者的中性臉</translation>
    </message>
    <message>
        <source>Record the performance onto the timeline at the playhead</source>
        <translation>將表演錄製到時間軸的播放頭處</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>來源：</translation>
    </message>
    <message>
        <source>&lt;b&gt;Performer&lt;/b&gt;</source>
        <translation>&lt;b&gt;表演者&lt;/b&gt;</translation>
    </message>
    <message>
        <source>The next frame becomes the rest pose…</source>
        <translation>下一個影格會成為靜止姿勢…</translation>
    </message>
    <message>
        <source>Open a photo with a face first: the cartoon of that face follows the performer.</source>
        <translation>請先開啟一張有臉的照片：那張臉的卡通會跟著表演者動。</translation>
    </message>
    <message>
        <source>No camera</source>
        <translation>沒有攝影機</translation>
    </message>
    <message>
        <source>Choose “Video file…” to perform from a clip.</source>
        <translation>選擇「影片檔案…」以從片段表演。</translation>
    </message>
    <message>
        <source>Choose a camera or a video file.</source>
        <translation>選擇攝影機或影片檔案。</translation>
    </message>
    <message>
        <source>Camera: %1</source>
        <translation>攝影機：%1</translation>
    </message>
    <message>
        <source>Video file…</source>
        <translation>影片檔案…</translation>
    </message>
    <message>
        <source>Perform from a Video</source>
        <translation>從影片表演</translation>
    </message>
    <message>
        <source>Videos (*.mp4 *.mov *.mkv *.avi *.mpg *.mpeg *.webm);;All files (*)</source>
        <translation>影片 (*.mp4 *.mov *.mkv *.avi *.mpg *.mpeg *.webm);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Camera “%1”: look straight at it with a relaxed face</source>
        <translation>攝影機「%1」：請放鬆臉部並直視鏡頭</translation>
    </message>
    <message>
        <source>Video file: %1</source>
        <translation>影片檔案：%1</translation>
    </message>
    <message>
        <source>Playing %1 as the performer</source>
        <translation>正在播放 %1 作為表演者</translation>
    </message>
    <message>
        <source>The clip has no sound: the mouth follows the camera.</source>
        <translation>片段沒有聲音：嘴巴跟隨攝影機。</translation>
    </message>
    <message>
        <source>The mouth follows the camera.</source>
        <translation>嘴巴跟隨攝影機。</translation>
    </message>
    <message>
        <source>Start a camera or a clip, with a face open, before recording.</source>
        <translation>錄製前請先啟動攝影機或片段，並開啟一張臉。</translation>
    </message>
    <message>
        <source>■ &amp;Stop</source>
        <translation>■ 停止(&amp;S)</translation>
    </message>
    <message>
        <source>Recording: motion only (no microphone)</source>
        <translation>錄製中：只有動作（沒有麥克風）</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>錄製中…</translation>
    </message>
    <message>
        <source>No frames yet.</source>
        <translation>還沒有影格。</translation>
    </message>
    <message>
        <source>Frames shown: %1 of %2
Latency to the picture: %3 ms (95 %: %4 ms)
Face lost in %5 frames%6</source>
        <translation>已顯示影格：%1 / %2
到畫面的延遲：%3 毫秒（95 %：%4 毫秒）
跟丟臉部的影格：%5 個%6</translation>
    </message>
    <message>
        <source>
● Recording</source>
        <translation>
● 錄製中</translation>
    </message>
</context>
<context>
    <name>toonface::MainWindow</name>
    <message>
        <source>Appearance</source>
        <translation>外觀</translation>
    </message>
    <message>
        <source>%1%</source>
        <translation>%1%</translation>
    </message>
    <message>
        <source>Detecting the face: %1</source>
        <translation>正在偵測臉部：%1</translation>
    </message>
    <message>
        <source>Landmark model unavailable (%1): detection may fail, but points can be placed by hand.</source>
        <translation>無法使用關鍵點模型（%1）：偵測可能失敗，但仍可手動放置特徵點。</translation>
    </message>
    <message>
        <source>&amp;Open Photo or Project…</source>
        <translation>開啟照片或專案(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>儲存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存新檔(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Export Cartoon…</source>
        <translation>匯出卡通(&amp;E)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>復原(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Re-&amp;detect Points</source>
        <translation>重新偵測特徵點(&amp;D)</translation>
    </message>
    <message>
        <source>Detect the face again and replace every point</source>
        <translation>重新偵測臉部並取代所有特徵點</translation>
    </message>
    <message>
        <source>Re-detect &amp;Keeping My Points</source>
        <translation>重新偵測並保留我的特徵點(&amp;K)</translation>
    </message>
    <message>
        <source>Detect the face again but keep the points placed by hand</source>
        <translation>重新偵測臉部，但保留手動放置的特徵點</translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation>自動(&amp;A)</translation>
    </message>
    <message>
        <source>The landmark model where it is installed, the thesis pipeline where it is not</source>
        <translation>有安裝關鍵點模型時使用它，沒有時使用論文流程</translation>
    </message>
    <message>
        <source>&amp;Thesis Pipeline (Classic)</source>
        <translation>論文流程（經典）(&amp;T)</translation>
    </message>
    <message>
        <source>The thesis&apos; steps only: thresholds, eye pair, edges and feature regions; best on a plain background with frontal light</source>
        <translation>只用論文的步驟：閾值、雙眼配對、邊緣與五官區域；最適合素色背景與正面光線</translation>
    </message>
    <message>
        <source>&amp;Landmarks</source>
        <translation>關鍵點(&amp;L)</translation>
    </message>
    <message>
        <source>The landmark model&apos;s 68 points mapped to the face model, hair and ears found around them</source>
        <translation>關鍵點模型的 68 個點對應到臉部模型，並在其周圍找出頭髮與耳朵</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>縮小(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Actual Size</source>
        <translation>實際大小(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>符合視窗大小(&amp;F)</translation>
    </message>
    <message>
        <source>Zoom to F&amp;ace</source>
        <translation>縮放至臉部(&amp;A)</translation>
    </message>
    <message>
        <source>Show Point &amp;IDs</source>
        <translation>顯示特徵點編號(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;About Toonface</source>
        <translation>關於 Toonface(&amp;A)</translation>
    </message>
    <message>
        <source>About Toonface</source>
        <translation>關於 Toonface</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Toonface %1&lt;/h3&gt;&lt;p&gt;Personal talking cartoon faces from photos, drawn in SVG.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Toonface %1&lt;/h3&gt;&lt;p&gt;用照片做出會說話的個人卡通臉，以 SVG 繪製。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近開啟的檔案(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>編輯(&amp;E)</translation>
    </message>
    <message>
        <source>Detection &amp;Method</source>
        <translation>偵測方法(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>主工具列</translation>
    </message>
    <message>
        <source>Style:</source>
        <translation>風格：</translation>
    </message>
    <message>
        <source>Drawing style of the cartoon</source>
        <translation>卡通的繪製風格</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Photos and projects (*.toonface %1);;Toonface projects (*.toonface);;Photos (%1);;All files (*)</source>
        <translation>照片與專案 (*.toonface %1);;Toonface 專案 (*.toonface);;照片 (%1);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Open Photo or Project</source>
        <translation>開啟照片或專案</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>正在開啟 %1…</translation>
    </message>
    <message>
        <source>Cannot Open</source>
        <translation>無法開啟</translation>
    </message>
    <message>
        <source>Restored unsaved work on %1.</source>
        <translation>已還原 %1 未儲存的工作。</translation>
    </message>
    <message>
        <source>Photo Missing</source>
        <translation>照片遺失</translation>
    </message>
    <message>
        <source>The project opened, but its photo could not be read:
%1</source>
        <translation>專案已開啟，但無法讀取它的照片：
%1</translation>
    </message>
    <message>
        <source>Detecting the face…</source>
        <translation>正在偵測臉部…</translation>
    </message>
    <message>
        <source>Detection Failed</source>
        <translation>偵測失敗</translation>
    </message>
    <message>
        <source>%1
The points are unchanged.</source>
        <translation>%1
特徵點維持不變。</translation>
    </message>
    <message>
        <source>Detection cancelled.</source>
        <translation>已取消偵測。</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Stop detecting the face</source>
        <translation>停止偵測臉部</translation>
    </message>
    <message>
        <source>Stop opening the file</source>
        <translation>停止開啟檔案</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>儲存專案</translation>
    </message>
    <message>
        <source>Toonface projects (*.toonface)</source>
        <translation>Toonface 專案 (*.toonface)</translation>
    </message>
    <message>
        <source>Cannot Save</source>
        <translation>無法儲存</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已儲存 %1。</translation>
    </message>
    <message>
        <source>Export Cartoon</source>
        <translation>匯出卡通</translation>
    </message>
    <message>
        <source>SVG image (*.svg);;PNG image (*.png)</source>
        <translation>SVG 影像 (*.svg);;PNG 影像 (*.png)</translation>
    </message>
    <message>
        <source>Exported %1.</source>
        <translation>已匯出 %1。</translation>
    </message>
    <message>
        <source>Cannot Export</source>
        <translation>無法匯出</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>未儲存的變更</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 有未儲存的變更。要儲存嗎？</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>清除選單(&amp;C)</translation>
    </message>
    <message>
        <source>%1[*] — Toonface</source>
        <translation>%1[*] — Toonface</translation>
    </message>
    <message>
        <source>The detection&apos;s steps appear when it ends</source>
        <translation>偵測結束後會顯示其步驟</translation>
    </message>
    <message>
        <source>Open a photo: its face detection&apos;s steps can be shown here</source>
        <translation>開啟照片：這裡可以顯示其臉部偵測的步驟</translation>
    </message>
    <message>
        <source>No detection steps for this photo: they are not saved in projects. Use Edit ▸ Re-detect Points to see them</source>
        <translation>這張照片沒有偵測步驟：專案不會儲存它們。請使用「編輯 ▸ 重新偵測特徵點」來查看</translation>
    </message>
    <message>
        <source>Style “%1”</source>
        <translation>風格「%1」</translation>
    </message>
    <message>
        <source>Point %1 (%2) at %3, %4</source>
        <translation>特徵點 %1（%2）位於 %3, %4</translation>
    </message>
    <message>
        <source> · control point</source>
        <translation> · 控制點</translation>
    </message>
    <message>
        <source> · placed by hand</source>
        <translation> · 手動放置</translation>
    </message>
</context>
<context>
    <name>toonface::MediaAudioTrack</name>
    <message>
        <source>Cannot play the audio file %1: %2</source>
        <translation>無法播放音訊檔案 %1：%2</translation>
    </message>
    <message>
        <source>The audio file %1 %2.</source>
        <translation>音訊檔案 %1 %2。</translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <source>is missing</source>
        <translation>遺失</translation>
    </message>
</context>
<context>
    <name>toonface::Microphone</name>
    <message>
        <source>No microphone was found: the sound cannot drive the mouth, and recordings keep the motion only.</source>
        <translation>找不到麥克風：聲音無法驅動嘴巴，錄製時只保留動作。</translation>
    </message>
    <message>
        <source>The microphone “%1” cannot be opened.</source>
        <translation>無法開啟麥克風「%1」。</translation>
    </message>
    <message>
        <source>The microphone “%1” stopped.</source>
        <translation>麥克風「%1」已停止。</translation>
    </message>
</context>
<context>
    <name>toonface::MouthShapesDialog</name>
    <message>
        <source>lips shut (b p m, rest)</source>
        <translation>雙唇閉合（b p m、靜止）</translation>
    </message>
    <message>
        <source>lower lip under the upper (f)</source>
        <translation>下唇在上齒下（f）</translation>
    </message>
    <message>
        <source>open (most initials, ng, er)</source>
        <translation>張開（多數聲母、ng、er）</translation>
    </message>
    <message>
        <source>wide open (a)</source>
        <translation>大張（a）</translation>
    </message>
    <message>
        <source>spread (i, y)</source>
        <translation>展唇（i、y）</translation>
    </message>
    <message>
        <source>rounded (u, w)</source>
        <translation>圓唇（u、w）</translation>
    </message>
    <message>
        <source>half open, spread (e)</source>
        <translation>半開展唇（e）</translation>
    </message>
    <message>
        <source>round open (o)</source>
        <translation>圓唇張開（o）</translation>
    </message>
    <message>
        <source>tongue up (n)</source>
        <translation>舌尖上抬（n）</translation>
    </message>
    <message>
        <source>Upper lip 8.9</source>
        <translation>上唇 8.9</translation>
    </message>
    <message>
        <source>Lower lip 8.2</source>
        <translation>下唇 8.2</translation>
    </message>
    <message>
        <source>Left corner 8.4</source>
        <translation>左嘴角 8.4</translation>
    </message>
    <message>
        <source>Right corner 8.3</source>
        <translation>右嘴角 8.3</translation>
    </message>
    <message>
        <source>Corners at the height &amp;midway between the lips (as o)</source>
        <translation>嘴角位於雙唇中間的高度(&amp;M)（如 o）</translation>
    </message>
    <message>
        <source>Corners stay where the shape &amp;before put them (as n)</source>
        <translation>嘴角停在前一個口型的位置(&amp;B)（如 n）</translation>
    </message>
    <message>
        <source>&amp;Reset Shape</source>
        <translation>重設口型(&amp;R)</translation>
    </message>
    <message>
        <source>Mouth Shapes</source>
        <translation>口型</translation>
    </message>
    <message>
        <source>Drag a point to move it</source>
        <translation>拖曳特徵點來移動它</translation>
    </message>
    <message>
        <source>How the four mouth control points move</source>
        <translation>四個嘴部控制點如何移動</translation>
    </message>
    <message>
        <source>On this face MNS0 (nose to mouth) = %1 px, MW0 (mouth width) = %2 px, LowerLipH = %3 px, ES0/100 = %4 px. y grows downwards.</source>
        <translation>在這張臉上 MNS0（鼻到嘴）= %1 像素，MW0（嘴寬）= %2 像素，LowerLipH = %3 像素，ES0/100 = %4 像素。y 向下增加。</translation>
    </message>
    <message>
        <source>Reset &amp;All</source>
        <translation>全部重設(&amp;A)</translation>
    </message>
    <message>
        <source>× MNS0</source>
        <translation>× MNS0</translation>
    </message>
    <message>
        <source>× MW0</source>
        <translation>× MW0</translation>
    </message>
    <message>
        <source>× LowerLipH</source>
        <translation>× LowerLipH</translation>
    </message>
    <message>
        <source>× ES0/100</source>
        <translation>× ES0/100</translation>
    </message>
    <message>
        <source>= pixels here</source>
        <translation>= 此處的像素</translation>
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
        <translation> （已編輯）</translation>
    </message>
    <message>
        <source> •</source>
        <translation> •</translation>
    </message>
    <message>
        <source>Edit Mouth Shapes</source>
        <translation>編輯口型</translation>
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
        <translation>悲傷</translation>
    </message>
    <message>
        <source>Angry</source>
        <translation>生氣</translation>
    </message>
    <message>
        <source>Surprise</source>
        <translation>驚訝</translation>
    </message>
    <message>
        <source>Normal</source>
        <comment>drawing style</comment>
        <translation>一般</translation>
    </message>
    <message>
        <source>Soft</source>
        <comment>drawing style</comment>
        <translation>柔和</translation>
    </message>
    <message>
        <source>Bold</source>
        <comment>drawing style</comment>
        <translation>粗獷</translation>
    </message>
    <message>
        <source>Cute</source>
        <comment>drawing style</comment>
        <translation>可愛</translation>
    </message>
    <message>
        <source>Angular</source>
        <comment>eyebrow variant</comment>
        <translation>稜角</translation>
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
        <translation>簡約</translation>
    </message>
    <message>
        <source>Tip only</source>
        <comment>nose variant</comment>
        <translation>只畫鼻頭</translation>
    </message>
    <message>
        <source>None</source>
        <comment>glasses</comment>
        <translation>無</translation>
    </message>
    <message>
        <source>Round</source>
        <comment>glasses</comment>
        <translation>圓框</translation>
    </message>
    <message>
        <source>Rectangular</source>
        <comment>glasses</comment>
        <translation>方框</translation>
    </message>
    <message>
        <source>Rimless</source>
        <comment>glasses</comment>
        <translation>無框</translation>
    </message>
    <message>
        <source>landmark</source>
        <comment>detection method</comment>
        <translation>關鍵點</translation>
    </message>
    <message>
        <source>classic</source>
        <comment>detection method</comment>
        <translation>經典</translation>
    </message>
</context>
<context>
    <name>toonface::PhotoView</name>
    <message>
        <source>Another face in the photo: click to use it instead</source>
        <translation>照片中的另一張臉：按一下改用它</translation>
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
        <translation>停止並回到第一個影格</translation>
    </message>
    <message>
        <source>&amp;Loop</source>
        <translation>循環(&amp;L)</translation>
    </message>
    <message>
        <source>Loop: play from the start again at the end</source>
        <translation>循環：播放到結尾後從頭再播</translation>
    </message>
    <message>
        <source>&amp;First Frame</source>
        <translation>第一個影格(&amp;F)</translation>
    </message>
    <message>
        <source>Pre&amp;vious Frame</source>
        <translation>上一個影格(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>下一個影格(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Last Frame</source>
        <translation>最後一個影格(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>暫停(&amp;P)</translation>
    </message>
    <message>
        <source>%1 Playing without sound.</source>
        <translation>%1 無聲播放。</translation>
    </message>
    <message>
        <source>The audio file %1 is missing: playing without sound.</source>
        <translation>找不到音訊檔案 %1：無聲播放。</translation>
    </message>
    <message>
        <source>No audio output device: playing without sound.</source>
        <translation>沒有音訊輸出裝置：無聲播放。</translation>
    </message>
    <message>
        <source>Nothing to play: the timeline is empty.</source>
        <translation>沒有可播放的內容：時間軸是空的。</translation>
    </message>
</context>
<context>
    <name>toonface::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>偏好設定</translation>
    </message>
    <message>
        <source>System (%1)</source>
        <translation>系統（%1）</translation>
    </message>
    <message>
        <source>The new language shows when Toonface is started again.</source>
        <translation>新的語言會在下次啟動 Toonface 時生效。</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
</context>
<context>
    <name>toonface::PreviewView</name>
    <message>
        <source>Edit &amp;Pose</source>
        <translation>編輯姿勢(&amp;P)</translation>
    </message>
    <message>
        <source>Show the control points on the preview: drag one to set a pose key frame at the playhead</source>
        <translation>在預覽上顯示控制點：拖曳其中一點即可在播放頭處設定姿勢關鍵影格</translation>
    </message>
    <message>
        <source>Open a photo to draw its cartoon.</source>
        <translation>開啟照片以繪製它的卡通。</translation>
    </message>
    <message>
        <source>No face points yet.</source>
        <translation>還沒有臉部特徵點。</translation>
    </message>
    <message>
        <source>Drawing the cartoon…</source>
        <translation>正在繪製卡通…</translation>
    </message>
</context>
<context>
    <name>toonface::Questions</name>
    <message>
        <source>an untitled project</source>
        <translation>一個未命名的專案</translation>
    </message>
    <message>
        <source>Restore Unsaved Work</source>
        <translation>還原未儲存的工作</translation>
    </message>
    <message>
        <source>Toonface did not close properly. Unsaved work on %1 from %2 was kept.</source>
        <translation>Toonface 上次沒有正常關閉。已保留 %2 時 %1 未儲存的工作。</translation>
    </message>
    <message>
        <source>Restore it? Discarding deletes the kept copy.</source>
        <translation>要還原嗎？捨棄會刪除保留的副本。</translation>
    </message>
    <message>
        <source>&amp;Restore</source>
        <translation>還原(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>捨棄(&amp;D)</translation>
    </message>
    <message>
        <source>No face was found in %1.</source>
        <translation>在 %1 中找不到臉。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>No Face Found</source>
        <translation>找不到臉</translation>
    </message>
    <message>
        <source>You can place an average face on the photo and drag its points into place by hand.</source>
        <translation>您可以在照片上放一張平均臉，再手動把特徵點拖曳到正確位置。</translation>
    </message>
    <message>
        <source>&amp;Place Average Face</source>
        <translation>放置平均臉(&amp;P)</translation>
    </message>
    <message>
        <source>Place average face</source>
        <translation>放置平均臉</translation>
    </message>
</context>
<context>
    <name>toonface::SayTextDialog</name>
    <message>
        <source>Say</source>
        <translation>朗讀</translation>
    </message>
    <message>
        <source>Say Text</source>
        <translation>說出文字</translation>
    </message>
    <message>
        <source>The built-in voice speaks the text and the face says it with the voice&apos;s exact timings. The mouth keys and syllables where the speech plays are replaced.</source>
        <translation>內建語音朗讀文字，臉部依語音的精確時間說出來。語音播放範圍內的口型關鍵影格與音節會被取代。</translation>
    </message>
    <message>
        <source>Chinese characters, pinyin, Zhuyin or English, e.g. 您好，我是葛麗絲。</source>
        <translation>漢字、拼音、注音或英文，例如：您好，我是葛麗絲。</translation>
    </message>
    <message>
        <source> words/min</source>
        <translation> 字/分鐘</translation>
    </message>
    <message>
        <source>Where the speech starts on the timeline</source>
        <translation>語音在時間軸上的開始位置</translation>
    </message>
    <message>
        <source>Pitch:</source>
        <translation>音高：</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>選擇…</translation>
    </message>
    <message>
        <source>The sound is saved beside the project.</source>
        <translation>聲音會儲存在專案旁邊。</translation>
    </message>
    <message>
        <source>The project is not saved yet: the sound is saved in your documents folder.</source>
        <translation>專案尚未儲存：聲音會儲存在您的文件資料夾中。</translation>
    </message>
    <message>
        <source>The project is not saved yet: the sound is saved beside the photo. Save the project in the same folder to keep them together.</source>
        <translation>專案尚未儲存：聲音會儲存在照片旁邊。請將專案儲存在同一個資料夾，讓它們放在一起。</translation>
    </message>
    <message>
        <source>&amp;Text:</source>
        <translation>文字(&amp;T)：</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>速度(&amp;S)：</translation>
    </message>
    <message>
        <source>Starts &amp;at:</source>
        <translation>開始於(&amp;A)：</translation>
    </message>
    <message>
        <source>Save the s&amp;ound as:</source>
        <translation>聲音儲存為(&amp;O)：</translation>
    </message>
    <message>
        <source>Save the Sound As</source>
        <translation>聲音另存為</translation>
    </message>
    <message>
        <source>WAV sound (*.wav)</source>
        <translation>WAV 聲音 (*.wav)</translation>
    </message>
    <message>
        <source>The text has nothing to say.</source>
        <translation>文字中沒有可說的內容。</translation>
    </message>
    <message>
        <source>Speaking</source>
        <translation>正在朗讀</translation>
    </message>
    <message>
        <source>%1: cannot create its folder</source>
        <translation>%1：無法建立其資料夾</translation>
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
        <translation>口型 %1（按鍵 %2）：取代所選的口型關鍵影格，或在播放頭處插入一個</translation>
    </message>
</context>
<context>
    <name>toonface::SpeechDialog</name>
    <message>
        <source>Nothing was changed.</source>
        <translation>沒有任何變更。</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>Cancelled: nothing was changed.</source>
        <translation>已取消：沒有任何變更。</translation>
    </message>
</context>
<context>
    <name>toonface::StepImageDialog</name>
    <message>
        <source>No picture.</source>
        <translation>沒有畫面。</translation>
    </message>
</context>
<context>
    <name>toonface::Studio</name>
    <message>
        <source>&amp;Lip Sync from Recording…</source>
        <translation>依錄音做唇形同步(&amp;L)…</translation>
    </message>
    <message>
        <source>Time the mouth to a speech recording and its script</source>
        <translation>讓嘴巴配合語音錄音及其文稿的時間</translation>
    </message>
    <message>
        <source>&amp;Say Text…</source>
        <translation>說出文字(&amp;S)…</translation>
    </message>
    <message>
        <source>Speak a text with the built-in voice and lip-sync the face to it</source>
        <translation>以內建語音朗讀文字，並讓臉部對嘴</translation>
    </message>
    <message>
        <source>Add &amp;Blinks…</source>
        <translation>加入眨眼(&amp;B)…</translation>
    </message>
    <message>
        <source>Add &amp;Emotion…</source>
        <translation>加入表情(&amp;E)…</translation>
    </message>
    <message>
        <source>&amp;Mouth Shapes…</source>
        <translation>口型(&amp;M)…</translation>
    </message>
    <message>
        <source>Edit this character&apos;s nine mouth shapes</source>
        <translation>編輯這個角色的九種口型</translation>
    </message>
    <message>
        <source>Export &amp;Animation…</source>
        <translation>匯出動畫(&amp;A)…</translation>
    </message>
    <message>
        <source>Export the animation as SVG, HTML, MP4, GIF or PNG frames</source>
        <translation>將動畫匯出為 SVG、HTML、MP4、GIF 或 PNG 影格</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>動畫(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Timeline</source>
        <translation>時間軸(&amp;T)</translation>
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
        <translation>匯入影片(&amp;V)…</translation>
    </message>
    <message>
        <source>Track a clip of a person speaking and put the motion on the timeline</source>
        <translation>追蹤人物說話的片段，並將動作放到時間軸上</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>已匯入 %1</translation>
    </message>
    <message>
        <source>Show the imported clip beside the cartoon</source>
        <translation>在卡通旁顯示匯入的片段</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>偏好設定(&amp;F)…</translation>
    </message>
    <message>
        <source>Choose the language of the interface</source>
        <translation>選擇介面的語言</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>已匯出 %1</translation>
    </message>
    <message>
        <source>Capture from &amp;Camera…</source>
        <translation>從攝影機擷取(&amp;C)…</translation>
    </message>
    <message>
        <source>Take the neutral photo with a camera</source>
        <translation>用攝影機拍攝中性照片</translation>
    </message>
    <message>
        <source>&amp;Live Mode…</source>
        <translation>即時模式(&amp;L)…</translation>
    </message>
    <message>
        <source>Puppeteer the cartoon live from a camera or a video, and record the performance</source>
        <translation>用攝影機或影片即時操控卡通，並錄製表演</translation>
    </message>
    <message>
        <source>Camera photo saved as %1</source>
        <translation>攝影機照片已儲存為 %1</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>時間軸</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineEdits</name>
    <message>
        <source>the clipboard holds no timeline items</source>
        <translation>剪貼簿中沒有時間軸項目</translation>
    </message>
    <message>
        <source>the clipboard&apos;s timeline items are damaged: %1</source>
        <translation>剪貼簿中的時間軸項目已損壞：%1</translation>
    </message>
    <message>
        <source>no syllable %1</source>
        <translation>沒有第 %1 個音節</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an English word: it has no pinyin</source>
        <translation>「%1」是英文單字：沒有拼音</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a Mandarin syllable</source>
        <translation>「%1」不是華語音節</translation>
    </message>
</context>
<context>
    <name>toonface::TimelineView</name>
    <message>
        <source>Reading the sound…</source>
        <translation>正在讀取聲音…</translation>
    </message>
    <message>
        <source>Move on Timeline</source>
        <translation>在時間軸上移動</translation>
    </message>
    <message>
        <source>Retime Syllable</source>
        <translation>調整音節時間</translation>
    </message>
    <message>
        <source>Resize on Timeline</source>
        <translation>在時間軸上調整長度</translation>
    </message>
    <message>
        <source>Change Emotion Fade</source>
        <translation>變更表情淡入淡出</translation>
    </message>
    <message>
        <source>Change Emotion Intensity</source>
        <translation>變更表情強度</translation>
    </message>
    <message>
        <source>Change Mouth Weight</source>
        <translation>變更口型權重</translation>
    </message>
    <message>
        <source>Delete from Timeline</source>
        <translation>從時間軸刪除</translation>
    </message>
    <message>
        <source>Paste on Timeline</source>
        <translation>貼到時間軸</translation>
    </message>
    <message>
        <source>Replace Mouth Shape</source>
        <translation>取代口型</translation>
    </message>
    <message>
        <source>Insert Mouth Shape</source>
        <translation>插入口型</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>加入表情</translation>
    </message>
    <message>
        <source>Regenerate Blinks</source>
        <translation>重新產生眨眼</translation>
    </message>
    <message>
        <source>Add Head Shake</source>
        <translation>加入搖頭</translation>
    </message>
    <message>
        <source>Add Head Nod</source>
        <translation>加入點頭</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an English word: only Mandarin syllables have pinyin to edit</source>
        <translation>「%1」是英文單字：只有華語音節才有可編輯的拼音</translation>
    </message>
    <message>
        <source>Change Syllable</source>
        <translation>變更音節</translation>
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
        <translation>縮小</translation>
    </message>
    <message>
        <source>Zoom to Fit</source>
        <translation>縮放至適合大小</translation>
    </message>
    <message>
        <source>Snap to Frames and Syllables</source>
        <translation>對齊影格與音節</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>刪除</translation>
    </message>
    <message>
        <source>Copy Keys</source>
        <translation>複製關鍵影格</translation>
    </message>
    <message>
        <source>Paste Keys at Playhead</source>
        <translation>在播放頭處貼上關鍵影格</translation>
    </message>
    <message>
        <source>Select All in Row</source>
        <translation>選取整列</translation>
    </message>
    <message>
        <source>Regenerate Blinks</source>
        <translation>重新產生眨眼</translation>
    </message>
    <message>
        <source>Add Head Shake</source>
        <translation>加入搖頭</translation>
    </message>
    <message>
        <source>Add Head Nod</source>
        <translation>加入點頭</translation>
    </message>
    <message>
        <source>Apply %1</source>
        <translation>套用%1</translation>
    </message>
    <message>
        <source>Replace Shape</source>
        <translation>取代口型</translation>
    </message>
    <message>
        <source>Insert Shape</source>
        <translation>插入口型</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>粗細</translation>
    </message>
    <message>
        <source>Add Emotion</source>
        <translation>加入表情</translation>
    </message>
    <message>
        <source>Edit Pinyin…</source>
        <translation>編輯拼音…</translation>
    </message>
</context>
<context>
    <name>toonface::VideoDock</name>
    <message>
        <source>Video</source>
        <translation>影片</translation>
    </message>
</context>
<context>
    <name>toonface::VideoView</name>
    <message>
        <source>No video: Animation ▸ Import Video… tracks a clip and shows it here.</source>
        <translation>沒有影片：「動畫 ▸ 匯入影片…」會追蹤片段並在這裡顯示。</translation>
    </message>
    <message>
        <source>The clip starts at %1 s</source>
        <translation>片段從 %1 秒開始</translation>
    </message>
    <message>
        <source>The clip ended at %1 s</source>
        <translation>片段在 %1 秒結束</translation>
    </message>
    <message>
        <source>frame %1 · %2 s</source>
        <translation>第 %1 個影格 · %2 秒</translation>
    </message>
    <message>
        <source>frame %1</source>
        <translation>第 %1 個影格</translation>
    </message>
</context>
<context>
    <name>toonface::cli::Cli</name>
    <message>
        <source>The speech recording.</source>
        <translation>語音錄音。</translation>
    </message>
    <message>
        <source>The recording&apos;s script (a UTF-8 text file).</source>
        <translation>錄音的文稿（UTF-8 文字檔）。</translation>
    </message>
    <message>
        <source>Speak this text with the built-in voice.</source>
        <translation>用內建語音說出這段文字。</translation>
    </message>
    <message>
        <source>Drive the face by a video of the person.</source>
        <translation>用該人物的影片驅動臉部。</translation>
    </message>
    <message>
        <source>Language of the script: cmn or en (default: detected).</source>
        <translation>文稿的語言：cmn 或 en（預設：自動偵測）。</translation>
    </message>
    <message>
        <source>Expression while speaking: neutral, smile, sad, angry or surprise.</source>
        <translation>說話時的表情：neutral、smile、sad、angry 或 surprise。</translation>
    </message>
    <message>
        <source>Do not blink.</source>
        <translation>不眨眼。</translation>
    </message>
    <message>
        <source>Frames per second (default 25).</source>
        <translation>每秒影格數（預設 25）。</translation>
    </message>
    <message>
        <source>Drawing style: %1.</source>
        <translation>繪製風格：%1。</translation>
    </message>
    <message>
        <source>Also save the result as a project.</source>
        <translation>同時將結果儲存為專案。</translation>
    </message>
    <message>
        <source>OUT.svg, OUT.html, OUT.mp4, OUT.gif, or DIR/ for PNG frames.</source>
        <translation>OUT.svg、OUT.html、OUT.mp4、OUT.gif，或 PNG 影格用的 DIR/。</translation>
    </message>
    <message>
        <source>A photo or a project; or a video clip, whose neutral frame&apos;s face it animates.</source>
        <translation>照片或專案；或影片片段，以其中性影格的臉製作動畫。</translation>
    </message>
    <message>
        <source>animate takes one photo or project (usage: toonface-cli %1)</source>
        <translation>animate 只接受一張照片或一個專案（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>animate needs -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|DIR/</source>
        <translation>animate 需要 -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|DIR/</translation>
    </message>
    <message>
        <source>cannot tell the output type of &apos;%1&apos;: use .svg, .html, .mp4, .gif or a folder ending in /</source>
        <translation>無法判斷「%1」的輸出類型：請使用 .svg、.html、.mp4、.gif 或以 / 結尾的資料夾</translation>
    </message>
    <message>
        <source>animate needs exactly one of --audio with --script, --say TEXT or --video CLIP (a project without them plays its own timeline)</source>
        <translation>animate 需要以下其中一項：--audio 搭配 --script、--say TEXT 或 --video CLIP（沒有這些選項的專案會播放它自己的時間軸）</translation>
    </message>
    <message>
        <source>--audio and --script go together</source>
        <translation>--audio 與 --script 必須一起使用</translation>
    </message>
    <message>
        <source>--fps takes a number from 1 to 120, not &apos;%1&apos;</source>
        <translation>--fps 需要 1 到 120 的數字，而不是「%1」</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (cmn or en)</source>
        <translation>不明的 --lang「%1」（cmn 或 en）</translation>
    </message>
    <message>
        <source>animate takes a photo or a project, not a face JSON (%1)</source>
        <translation>animate 接受照片或專案，不接受臉部 JSON（%1）</translation>
    </message>
    <message>
        <source>%1: cannot write the neutral frame</source>
        <translation>%1：無法寫入中性影格</translation>
    </message>
    <message>
        <source>%1: the animation is silent</source>
        <translation>%1：動畫沒有聲音</translation>
    </message>
    <message>
        <source>%1: the clip has no sound; the animation is silent</source>
        <translation>%1：片段沒有聲音；動畫沒有聲音</translation>
    </message>
    <message>
        <source>animate needs one of --audio with --script, --say TEXT or --video CLIP (only a project plays its own timeline)</source>
        <translation>animate 需要以下其中一項：--audio 搭配 --script、--say TEXT 或 --video CLIP（只有專案會播放它自己的時間軸）</translation>
    </message>
    <message>
        <source>%1: the project has no animation to play (its timeline is empty)</source>
        <translation>%1：專案沒有可播放的動畫（時間軸是空的）</translation>
    </message>
    <message>
        <source>exporting %1 s of animation to %2</source>
        <translation>正在將 %1 秒的動畫匯出到 %2</translation>
    </message>
    <message>
        <source>exporting: %1 %</source>
        <translation>正在匯出：%1 %</translation>
    </message>
    <message>
        <source>Make the face of a photo or project talk, and export the animation (SVG, HTML, MP4, GIF or PNG frames).</source>
        <translation>讓照片或專案中的臉說話，並匯出動畫（SVG、HTML、MP4、GIF 或 PNG 影格）。</translation>
    </message>
    <message>
        <source>The cartoon SVG to write.</source>
        <translation>要寫入的卡通 SVG。</translation>
    </message>
    <message>
        <source>Also rasterize to this PNG.</source>
        <translation>同時點陣化為此 PNG。</translation>
    </message>
    <message>
        <source>The PNG&apos;s longer side in pixels (default 512).</source>
        <translation>PNG 的長邊像素數（預設 512）。</translation>
    </message>
    <message>
        <source>Expression: neutral, smile, sad, angry or surprise.</source>
        <translation>表情：neutral、smile、sad、angry 或 surprise。</translation>
    </message>
    <message>
        <source>Detection method for a photo: auto, classic or landmarks.</source>
        <translation>照片的偵測方法：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>How much to exaggerate what makes the face its own: 0 (exact) to 1 (default: the style&apos;s).</source>
        <translation>誇張這張臉獨有特徵的程度：0（寫實）到 1（預設：依風格）。</translation>
    </message>
    <message>
        <source>A photo, a face JSON or a project.</source>
        <translation>照片、臉部 JSON 或專案。</translation>
    </message>
    <message>
        <source>cartoon takes one input (usage: toonface-cli %1)</source>
        <translation>cartoon 只接受一個輸入（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>cartoon needs -o OUT.svg</source>
        <translation>cartoon 需要 -o OUT.svg</translation>
    </message>
    <message>
        <source>--size takes a whole number from 16 to 8192, not &apos;%1&apos;</source>
        <translation>--size 需要 16 到 8192 的整數，而不是「%1」</translation>
    </message>
    <message>
        <source>--caricature takes a number from 0 to 1, not &apos;%1&apos;</source>
        <translation>--caricature 需要 0 到 1 的數字，而不是「%1」</translation>
    </message>
    <message>
        <source>Draw the cartoon face of a photo, a face JSON or a project as SVG (and PNG).</source>
        <translation>將照片、臉部 JSON 或專案的卡通臉繪製為 SVG（以及 PNG）。</translation>
    </message>
    <message>
        <source>Detection method: auto, classic or landmarks.</source>
        <translation>偵測方法：auto、classic 或 landmarks。</translation>
    </message>
    <message>
        <source>Write the face JSON here (default: stdout).</source>
        <translation>將臉部 JSON 寫到這裡（預設：標準輸出）。</translation>
    </message>
    <message>
        <source>Write intermediate images of the detection here.</source>
        <translation>將偵測的中間影像寫到這裡。</translation>
    </message>
    <message>
        <source>With several faces, use the one at this point of the photo (pixels) instead of the largest, most central one.</source>
        <translation>有多張臉時，使用照片中這個點（像素）的臉，而不是最大、最靠中央的那張。</translation>
    </message>
    <message>
        <source>The photo.</source>
        <translation>照片。</translation>
    </message>
    <message>
        <source>detect takes one IMAGE (usage: toonface-cli %1)</source>
        <translation>detect 只接受一個 IMAGE（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>--face wants a point X,Y in photo pixels, not &apos;%1&apos;</source>
        <translation>--face 需要照片像素座標 X,Y，而不是「%1」</translation>
    </message>
    <message>
        <source>cannot create the debug folder %1</source>
        <translation>無法建立除錯資料夾 %1</translation>
    </message>
    <message>
        <source>Find the face in a photo and write its 72 points as JSON (toonface.face/1).</source>
        <translation>在照片中找出臉部，並將其 72 個特徵點寫成 JSON（toonface.face/1）。</translation>
    </message>
    <message>
        <source>The speech recording (WAV, FLAC, MP3, OGG, M4A or a video&apos;s sound).</source>
        <translation>語音錄音（WAV、FLAC、MP3、OGG、M4A 或影片的聲音）。</translation>
    </message>
    <message>
        <source>What is said, as UTF-8 text: Chinese characters, pinyin, zhuyin, or English.</source>
        <translation>說了什麼，UTF-8 文字：漢字、拼音、注音或英文。</translation>
    </message>
    <message>
        <source>Language of the script: cmn, en, or auto (from the script).</source>
        <translation>文稿的語言：cmn、en 或 auto（依文稿判斷）。</translation>
    </message>
    <message>
        <source>Write the result here: .tsv for Rhubarb-style cues, JSON otherwise (default: JSON on stdout).</source>
        <translation>將結果寫到這裡：.tsv 為 Rhubarb 格式的提示，其他為 JSON（預設：JSON 輸出到標準輸出）。</translation>
    </message>
    <message>
        <source>lipsync needs --audio and --script (usage: toonface-cli %1)</source>
        <translation>lipsync 需要 --audio 與 --script（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (cmn, en or auto)</source>
        <translation>不明的 --lang「%1」（cmn、en 或 auto）</translation>
    </message>
    <message>
        <source>aligning %1 with %2</source>
        <translation>正在對齊 %1 與 %2</translation>
    </message>
    <message>
        <source>Time a recording&apos;s syllables against its script and give the mouth shapes (toonface.lipsync/1).</source>
        <translation>將錄音的音節與文稿對齊時間，並給出口型（toonface.lipsync/1）。</translation>
    </message>
    <message>
        <source>Language of the text: cmn, en, or auto (from the text).</source>
        <translation>文字的語言：cmn、en 或 auto（依文字判斷）。</translation>
    </message>
    <message>
        <source>The speech: .wav, .flac, .mp3, .ogg, .opus or .m4a.</source>
        <translation>語音：.wav、.flac、.mp3、.ogg、.opus 或 .m4a。</translation>
    </message>
    <message>
        <source>Also write the exact syllable timings and mouth shapes (toonface.lipsync/1).</source>
        <translation>同時寫出精確的音節時間與口型（toonface.lipsync/1）。</translation>
    </message>
    <message>
        <source>An espeak-ng voice, optionally with a variant (cmn-latn-pinyin+f2).</source>
        <translation>espeak-ng 語音，可加上變體（cmn-latn-pinyin+f2）。</translation>
    </message>
    <message>
        <source>Words per minute (80-450).</source>
        <translation>每分鐘字數（80-450）。</translation>
    </message>
    <message>
        <source>Pitch, 0-100.</source>
        <translation>音高，0-100。</translation>
    </message>
    <message>
        <source>What to say.</source>
        <translation>要說的話。</translation>
    </message>
    <message>
        <source>say takes one TEXT and -o OUT.wav (usage: toonface-cli %1)</source>
        <translation>say 只接受一段 TEXT 與 -o OUT.wav（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>--rate and --pitch take whole numbers</source>
        <translation>--rate 與 --pitch 需要整數</translation>
    </message>
    <message>
        <source>Speak a text with espeak-ng and write the exact syllable timings, so a face can talk without a recording.</source>
        <translation>用 espeak-ng 說出文字並寫出精確的音節時間，讓臉不需錄音也能說話。</translation>
    </message>
    <message>
        <source>Write the track JSON here (default: stdout).</source>
        <translation>將追蹤 JSON 寫到這裡（預設：標準輸出）。</translation>
    </message>
    <message>
        <source>The video of a speaking face.</source>
        <translation>人臉說話的影片。</translation>
    </message>
    <message>
        <source>track takes one VIDEO (usage: toonface-cli %1)</source>
        <translation>track 只接受一個 VIDEO（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>Track the face of a video frame by frame and write its motion as JSON (toonface.track/1).</source>
        <translation>逐影格追蹤影片中的臉，並將其動作寫成 JSON（toonface.track/1）。</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>顯示此說明。</translation>
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
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <source>%1: not a face JSON: %2 at offset %3</source>
        <translation>%1：不是臉部 JSON：%2，位於位移 %3</translation>
    </message>
    <message>
        <source>%1: the landmark method could not serve (%2); the points come from the classic method</source>
        <translation>%1：關鍵點方法無法使用（%2）；特徵點來自經典方法</translation>
    </message>
    <message>
        <source>%1: %2 faces found; the largest, most central one is used</source>
        <translation>%1：找到 %2 張臉；使用最大、最靠中央的那張</translation>
    </message>
    <message>
        <source>unknown --method &apos;%1&apos; (auto, classic or landmarks)</source>
        <translation>不明的 --method「%1」（auto、classic 或 landmarks）</translation>
    </message>
    <message>
        <source>unknown --emotion &apos;%1&apos; (neutral, smile, sad, angry or surprise)</source>
        <translation>不明的 --emotion「%1」（neutral、smile、sad、angry 或 surprise）</translation>
    </message>
    <message>
        <source>unknown --style &apos;%1&apos; (%2)</source>
        <translation>不明的 --style「%1」（%2）</translation>
    </message>
    <message>
        <source>What the drawing shows: head (framed square around the head, the default) or photo (the photo&apos;s whole frame, to lay over the photo).</source>
        <translation>繪圖的內容：head（頭部周圍的方形取景，預設）或 photo（照片的完整畫面，可疊在照片上）。</translation>
    </message>
    <message>
        <source>unknown --frame &apos;%1&apos; (head, photo)</source>
        <translation>不明的 --frame「%1」（head、photo）</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>無法建立資料夾 %1</translation>
    </message>
    <message>
        <source>--neutral-frame takes a frame number from 0, not &apos;%1&apos;</source>
        <translation>--neutral-frame 需要從 0 起算的影格編號，而不是「%1」</translation>
    </message>
    <message>
        <source>tracking %1: %2 %</source>
        <translation>正在追蹤 %1：%2 %</translation>
    </message>
    <message>
        <source>Toonface turns a photo into a personal cartoon face drawn in SVG and makes it talk.
Every job of the editor, with no display.</source>
        <translation>Toonface 把照片變成以 SVG 繪製的個人卡通臉，並讓它說話。
編輯器的每項工作，都不需要顯示器。</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>指令：</translation>
    </message>
    <message>
        <source>options of one command</source>
        <translation>單一指令的選項</translation>
    </message>
    <message>
        <source>the version</source>
        <translation>版本</translation>
    </message>
    <message>
        <source>Exit codes: 0 success, 2 usage, 3 unreadable or invalid input, 4 no face found,
5 the audio and the script could not be aligned, 1 other failures.</source>
        <translation>結束代碼：0 成功，2 用法錯誤，3 無法讀取或無效的輸入，4 找不到臉，
5 音訊與文稿無法對齊，1 其他失敗。</translation>
    </message>
    <message>
        <source>no command given; try &apos;toonface-cli --help&apos;</source>
        <translation>沒有指定指令；請試試「toonface-cli --help」</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;; try &apos;toonface-cli --help&apos;</source>
        <translation>不明的指令「%1」；請試試「toonface-cli --help」</translation>
    </message>
</context>
</TS>
