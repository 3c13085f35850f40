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
        <source>Move %1</source>
        <translation>移動%1</translation>
    </message>
</context>
<context>
    <name>PointHandle</name>
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
    <message>
        <source>%1 dB</source>
        <translation>%1 dB</translation>
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
    <name>toonface::AnimationEdits</name>
    <message>
        <source>placed after %1, at %2 s (it would have played over it)</source>
        <translation>已放在 %1 之後，位於 %2 秒（否則會與其重疊播放）</translation>
    </message>
    <message>
        <source>replaced %1</source>
        <translation>已取代 %1</translation>
    </message>
    <message>
        <source>plays together with %1</source>
        <translation>與 %1 同時播放</translation>
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
    <message>
        <source>Goatee</source>
        <translation>山羊鬍</translation>
    </message>
    <message>
        <source>Hair on the chin only (drawn when there is no beard)</source>
        <translation>只在下巴上的鬍子（沒有鬍鬚時才畫出）</translation>
    </message>
    <message>
        <source>A child is drawn with thin light brows, unpainted lips, a rounder jaw and larger eyes; an elderly person with fine age lines</source>
        <translation>兒童畫成細淡的眉毛、不塗色的嘴唇、較圓的下顎和較大的眼睛；長者畫上細細的皺紋</translation>
    </message>
    <message>
        <source>Adult</source>
        <translation>成人</translation>
    </message>
    <message>
        <source>Child</source>
        <translation>兒童</translation>
    </message>
    <message>
        <source>Elderly</source>
        <translation>長者</translation>
    </message>
    <message>
        <source>Age:</source>
        <translation>年齡：</translation>
    </message>
    <message>
        <source>Age</source>
        <translation>年齡</translation>
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
    <message>
        <source>The face is turned about %1° to the side.</source>
        <translation>臉轉向一側約 %1°。</translation>
    </message>
    <message>
        <source>The head is tilted about %1°.</source>
        <translation>頭傾斜約 %1°。</translation>
    </message>
    <message>
        <source>The cartoon is drawn from the front and will look twisted: a photo looking straight into the camera works best.</source>
        <translation>卡通是從正面畫的，會顯得扭曲：正面直視鏡頭的照片效果最好。</translation>
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
        <source>The &amp;whole animation (%1 s)</source>
        <translation>整段動畫（%1 秒）(&amp;W)</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
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
    <message>
        <source>Blinks at a person&apos;s pace: about one every three and a half seconds, now and then two in a row. The same pattern number always gives the same blinks.</source>
        <translation>以真人的節奏眨眼：大約每三秒半一次，偶爾連續兩次。同一個樣式編號總是產生相同的眨眼。</translation>
    </message>
    <message>
        <source>&amp;Shuffle</source>
        <translation>隨機(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Pattern:</source>
        <translation>樣式(&amp;P)：</translation>
    </message>
</context>
<context>
    <name>toonface::BookDialog</name>
    <message>
        <source>Export Read-aloud Book</source>
        <translation>匯出有聲書</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
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
        <translation>這段文字的錄音</translation>
    </message>
    <message>
        <source>The built-in voice</source>
        <translation>內建語音</translation>
    </message>
    <message>
        <source>&amp;Read by:</source>
        <translation>朗讀者(&amp;R)：</translation>
    </message>
    <message>
        <source>&amp;Recording:</source>
        <translation>錄音(&amp;R)：</translation>
    </message>
    <message>
        <source>Sound (*.wav *.flac *.mp3 *.ogg *.opus *.m4a)</source>
        <translation>聲音 (*.wav *.flac *.mp3 *.ogg *.opus *.m4a)</translation>
    </message>
    <message>
        <source>As the text reads</source>
        <translation>依文字判斷</translation>
    </message>
    <message>
        <source>Chinese (Traditional)</source>
        <translation>中文（繁體）</translation>
    </message>
    <message>
        <source>Chinese (Simplified)</source>
        <translation>中文（簡體）</translation>
    </message>
    <message>
        <source>English</source>
        <translation>英文</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
    <message>
        <source>The first heading, or the text&apos;s file name</source>
        <translation>第一個標題，或文字的檔名</translation>
    </message>
    <message>
        <source>T&amp;itle:</source>
        <translation>書名(&amp;I)：</translation>
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
        <translation>每個字或單字</translation>
    </message>
    <message>
        <source>&amp;Highlight:</source>
        <translation>標示(&amp;H)：</translation>
    </message>
    <message>
        <source>&amp;Book:</source>
        <translation>書(&amp;B)：</translation>
    </message>
    <message>
        <source>EPUB book (*.epub)</source>
        <translation>EPUB 書 (*.epub)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>匯出(&amp;E)</translation>
    </message>
    <message>
        <source>Export Read-aloud &amp;Book…</source>
        <translation>匯出有聲書(&amp;B)…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>正在開始…</translation>
    </message>
    <message numerus="yes">
        <source>Wrote %1: %n page(s)</source>
        <translation>
            <numerusform>已寫入 %1：%n 頁</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled; nothing was written.</source>
        <translation>已取消；沒有寫入任何檔案。</translation>
    </message>
    <message numerus="yes">
        <source>The project&apos;s audio track (%n recording(s), mixed)</source>
        <translation>
            <numerusform>專案的音軌（%n 段錄音，混音）</numerusform>
        </translation>
    </message>
    <message>
        <source>Mixing the recordings…</source>
        <translation>正在混合錄音…</translation>
    </message>
    <message>
        <source>An animated drawing</source>
        <translation>一張動畫圖</translation>
    </message>
    <message>
        <source>A video of each page</source>
        <translation>每一頁的影片</translation>
    </message>
    <message>
        <source>A video of each page read aloud plays in reading systems that neither read aloud nor animate drawings; it takes longer to make</source>
        <translation>每一頁朗讀的影片可在既不會朗讀、也不會播放動畫圖的閱讀器中播放；製作需要較長時間</translation>
    </message>
    <message>
        <source>&amp;Face:</source>
        <translation>臉(&amp;F)：</translation>
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
    <message>
        <source>there is no cache yet</source>
        <translation>還沒有快取</translation>
    </message>
    <message>
        <source>the cache could not be opened: %1</source>
        <translation>無法開啟快取：%1</translation>
    </message>
    <message>
        <source>the cache is cut short</source>
        <translation>快取不完整（檔案被截斷）</translation>
    </message>
    <message>
        <source>the file is not a cache of this kind</source>
        <translation>此檔案不是這一類的快取</translation>
    </message>
    <message>
        <source>the cache is of another version (%1)</source>
        <translation>快取屬於另一個版本（%1）</translation>
    </message>
    <message>
        <source>the cache was made from another model</source>
        <translation>快取是由另一個模型產生的</translation>
    </message>
    <message>
        <source>the cache is %1 bytes, not the %2 its header gives</source>
        <translation>快取有 %1 位元組，而不是標頭所記載的 %2</translation>
    </message>
    <message>
        <source>the cache could not be read: %1</source>
        <translation>無法讀取快取：%1</translation>
    </message>
    <message>
        <source>the cache is damaged (its checksum does not match)</source>
        <translation>快取已損壞（檢查碼不符）</translation>
    </message>
    <message>
        <source>the folder %1 could not be made</source>
        <translation>無法建立資料夾 %1</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>The image is too small for the classic method.</source>
        <translation>影像太小，無法使用經典方法。</translation>
    </message>
    <message>
        <source>No eye pair was found (the classic method needs a large frontal face on a plain background).</source>
        <translation>找不到一對眼睛（經典方法需要素色背景前的大張正面臉部）。</translation>
    </message>
    <message>
        <source>the point between the eyes is not in the face region</source>
        <translation>兩眼之間的點不在臉部區域內</translation>
    </message>
    <message>
        <source>the face region reaches %1 eye distances below it (%2 needed)</source>
        <translation>臉部區域向下只延伸 %1 個眼距（需要 %2）</translation>
    </message>
    <message>
        <source>%1 eye distances to its nearer side (%2 .. %3 needed)</source>
        <translation>到較近一側的距離為 %1 個眼距（需要 %2 .. %3）</translation>
    </message>
    <message>
        <source>no mouth row below it (the darkest row is %1% darker than the median, %2% needed)</source>
        <translation>下方沒有嘴巴所在的列（最暗的列比中位數暗 %1%，需要 %2%）</translation>
    </message>
    <message>
        <source>the best eye pair by eq. (3.5), at (%1, %2) and (%3, %4), has no face around it: %5</source>
        <translation>依式 (3.5) 最佳的一對眼睛位於 (%1, %2) 與 (%3, %4)，但周圍沒有臉部：%5</translation>
    </message>
    <message>
        <source>The classic method found an eye pair but could not place a face around it (a feature collapsed to nothing).</source>
        <translation>經典方法找到了一對眼睛，但無法在其周圍放置臉部（有個特徵縮成了零）。</translation>
    </message>
    <message>
        <source>The classic method found no face: %1.</source>
        <translation>經典方法找不到臉部：%1。</translation>
    </message>
    <message>
        <source>Face detection was cancelled.</source>
        <translation>臉部偵測已取消。</translation>
    </message>
    <message>
        <source>The image is empty.</source>
        <translation>影像是空的。</translation>
    </message>
    <message>
        <source>the cache is damaged (it holds no detector)</source>
        <translation>快取已損壞（其中沒有偵測器）</translation>
    </message>
    <message>
        <source>the cache is damaged (%1)</source>
        <translation>快取已損壞（%1）</translation>
    </message>
    <message>
        <source>no face to search around</source>
        <translation>沒有可供搜尋周圍的臉部</translation>
    </message>
    <message>
        <source>the face is too small</source>
        <translation>臉部太小</translation>
    </message>
    <message>
        <source>the head is outside the photo</source>
        <translation>頭部超出照片範圍</translation>
    </message>
    <message>
        <source>the face is outside the photo</source>
        <translation>臉部超出照片範圍</translation>
    </message>
    <message>
        <source>the face&apos;s central rectangle is dark</source>
        <translation>臉部中央的矩形太暗</translation>
    </message>
    <message>
        <source>the face region misses the face</source>
        <translation>臉部區域沒有涵蓋臉</translation>
    </message>
    <message>
        <source>the head&apos;s outline could not be followed (%1 of %2 searches ended on it)</source>
        <translation>無法沿著頭部輪廓追蹤（%2 次搜尋中只有 %1 次停在輪廓上）</translation>
    </message>
    <message>
        <source>no { } block of points</source>
        <translation>沒有 { } 點區塊</translation>
    </message>
    <message>
        <source>%1 numbers where %2 coordinates were expected</source>
        <translation>有 %1 個數字，但應有 %2 個座標</translation>
    </message>
    <message>
        <source>point %1 is not two numbers</source>
        <translation>第 %1 點不是兩個數字</translation>
    </message>
    <message>
        <source>is missing (install the package libdlib-data, or set TOONFACE_LANDMARK_MODEL to shape_predictor_68_face_landmarks.dat).</source>
        <translation>不存在（請安裝 libdlib-data 套件，或將 TOONFACE_LANDMARK_MODEL 設為 shape_predictor_68_face_landmarks.dat）。</translation>
    </message>
    <message>
        <source>The landmark model %1 %2</source>
        <translation>關鍵點模型 %1 %2</translation>
    </message>
    <message>
        <source>could not be read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <source>could not be opened.</source>
        <translation>無法開啟。</translation>
    </message>
    <message>
        <source>gives %1 points, not the 68 of the iBUG scheme.</source>
        <translation>有 %1 個點，而不是 iBUG 規格的 68 個。</translation>
    </message>
    <message>
        <source>could not be read: %1 at byte %2</source>
        <translation>無法讀取：%1（在第 %2 位元組）</translation>
    </message>
    <message>
        <source>could not be read: it ends early (at byte %1, in the middle of the model)</source>
        <translation>無法讀取：檔案提前結束（在第 %1 位元組，模型的中途）</translation>
    </message>
    <message>
        <source>could not be read: no memory for it (%1)</source>
        <translation>無法讀取：記憶體不足（%1）</translation>
    </message>
    <message>
        <source>could not be opened: %1</source>
        <translation>無法開啟：%1</translation>
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
        <translation>未命名專案</translation>
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
    <name>toonface::Export</name>
    <message>
        <source>no output file given</source>
        <translation>沒有指定輸出檔案</translation>
    </message>
    <message>
        <source>unsupported size %1 (from %2 to %3 pixels)</source>
        <translation>不支援的尺寸 %1（應為 %2 到 %3 像素）</translation>
    </message>
    <message>
        <source>unsupported frame rate %1 (more than 0, up to %2)</source>
        <translation>不支援的影格速率 %1（應大於 0，最多 %2）</translation>
    </message>
    <message>
        <source>cannot write: the folder %1 does not exist</source>
        <translation>無法寫入：資料夾 %1 不存在</translation>
    </message>
    <message>
        <source>cannot write PNG frames: it is a file, not a folder</source>
        <translation>無法寫入 PNG 影格：這是檔案，不是資料夾</translation>
    </message>
    <message>
        <source>cannot write: it is a folder</source>
        <translation>無法寫入：這是資料夾</translation>
    </message>
    <message>
        <source>cannot write: %1</source>
        <translation>無法寫入：%1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>cannot write: cannot create a folder in %1</source>
        <translation>無法寫入：無法在 %1 中建立資料夾</translation>
    </message>
    <message>
        <source>rendering stopped</source>
        <translation>繪製已停止</translation>
    </message>
    <message>
        <source>cannot write GIF: FFmpeg has no GIF encoder</source>
        <translation>無法寫入 GIF：FFmpeg 沒有 GIF 編碼器</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (GIF takes 1 to 65535 pixels a side)</source>
        <translation>不支援的尺寸 %1x%2（GIF 每邊須為 1 到 65535 像素）</translation>
    </message>
    <message>
        <source>cannot start the GIF encoder: %1</source>
        <translation>無法啟動 GIF 編碼器：%1</translation>
    </message>
    <message>
        <source>out of memory for a %1x%2 frame</source>
        <translation>記憶體不足，無法容納 %1x%2 的影格</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>記憶體不足</translation>
    </message>
    <message>
        <source>cannot write MP4: FFmpeg has no H.264 encoder (libx264)</source>
        <translation>無法寫入 MP4：FFmpeg 沒有 H.264 編碼器（libx264）</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (MP4 takes 2 to 8192 pixels a side)</source>
        <translation>不支援的尺寸 %1x%2（MP4 每邊須為 2 到 8192 像素）</translation>
    </message>
    <message>
        <source>cannot start the H.264 encoder at %1x%2: %3</source>
        <translation>無法以 %1x%2 啟動 H.264 編碼器：%3</translation>
    </message>
    <message>
        <source>cannot convert %1x%2 RGB to YUV</source>
        <translation>無法將 %1x%2 的 RGB 轉換為 YUV</translation>
    </message>
    <message>
        <source>cannot write MP4: FFmpeg has no AAC encoder</source>
        <translation>無法寫入 MP4：FFmpeg 沒有 AAC 編碼器</translation>
    </message>
    <message>
        <source>the writer is closed</source>
        <translation>寫入器已關閉</translation>
    </message>
    <message>
        <source>cannot write in the folder %1: %2</source>
        <translation>無法寫入資料夾 %1：%2</translation>
    </message>
    <message>
        <source>FFmpeg has no %1 muxer: %2</source>
        <translation>FFmpeg 沒有 %1 封裝器：%2</translation>
    </message>
    <message>
        <source>cannot write the header: %1</source>
        <translation>無法寫入標頭：%1</translation>
    </message>
    <message>
        <source>cannot set up the stream: %1</source>
        <translation>無法設定串流：%1</translation>
    </message>
    <message>
        <source>cannot encode (%1): %2</source>
        <translation>無法編碼（%1）：%2</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (PNG frames take 1 to 32768 pixels a side)</source>
        <translation>不支援的尺寸 %1x%2（PNG 影格每邊須為 1 到 32768 像素）</translation>
    </message>
    <message>
        <source>cannot create the folder for PNG frames</source>
        <translation>無法建立存放 PNG 影格的資料夾</translation>
    </message>
    <message>
        <source>unexpected head transform &apos;%1&apos;</source>
        <translation>非預期的頭部變換「%1」</translation>
    </message>
    <message>
        <source>the drawing has no head group</source>
        <translation>繪圖中沒有頭部群組</translation>
    </message>
    <message>
        <source>the drawing changes its structure with the pose</source>
        <translation>繪圖的結構會隨姿勢改變</translation>
    </message>
    <message>
        <source>the drawing is not valid XML: %1</source>
        <translation>繪圖不是有效的 XML：%1</translation>
    </message>
    <message>
        <source>the writer is already writing %1</source>
        <translation>寫入器正在寫入 %1</translation>
    </message>
    <message>
        <source>unsupported frame rate %1 (expected more than 0, up to 240)</source>
        <translation>不支援的影格速率 %1（應大於 0，最多 240）</translation>
    </message>
    <message>
        <source>unsupported size %1x%2</source>
        <translation>不支援的尺寸 %1x%2</translation>
    </message>
    <message>
        <source>the writer is not open</source>
        <translation>寫入器尚未開啟</translation>
    </message>
    <message>
        <source>an earlier frame failed; cancel the writer</source>
        <translation>先前的影格失敗了，請取消寫入</translation>
    </message>
    <message>
        <source>frame %1 is %2x%3, the video is %4x%5</source>
        <translation>第 %1 影格為 %2x%3，但影片為 %4x%5</translation>
    </message>
    <message>
        <source>an earlier frame failed; nothing was written</source>
        <translation>先前的影格失敗了，沒有寫入任何內容</translation>
    </message>
    <message>
        <source>no frames to write</source>
        <translation>沒有可寫入的影格</translation>
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
        <translation>不明的書籍語言「%1」（%2）</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1，第 %2 行</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be read aloud: %2</source>
        <translation>「%1」無法朗讀：%2</translation>
    </message>
    <message>
        <source>no room for temporary files: %1</source>
        <translation>沒有空間存放暫存檔：%1</translation>
    </message>
    <message>
        <source>reading the recording</source>
        <translation>正在讀取錄音</translation>
    </message>
    <message>
        <source>the recording (%1 s) is shorter than the text: its %2 words need at least %3 s even read fast (%4 a second)</source>
        <translation>錄音（%1 秒）比文字短：文字的 %2 個單字即使讀得很快（每秒 %4 個）也至少需要 %3 秒</translation>
    </message>
    <message>
        <source>the recording (%1 s) is shorter than the text: its %2 syllables need at least %3 s even read fast (%4 a second)</source>
        <translation>錄音（%1 秒）比文字短：文字的 %2 個音節即使讀得很快（每秒 %4 個）也至少需要 %3 秒</translation>
    </message>
    <message>
        <source>aligning the recording with the text</source>
        <translation>正在將錄音與文字對齊</translation>
    </message>
    <message>
        <source>%1 and %2 could not be aligned: syllables were lost</source>
        <translation>%1 與 %2 無法對齊：遺失了音節</translation>
    </message>
    <message>
        <source>cannot write beside it</source>
        <translation>無法在其旁邊寫入</translation>
    </message>
    <message>
        <source>cannot draw the cover</source>
        <translation>無法繪製封面</translation>
    </message>
    <message>
        <source>drawing the pages</source>
        <translation>正在繪製頁面</translation>
    </message>
    <message>
        <source>reading chapter %1 of %2 aloud</source>
        <translation>正在朗讀第 %1 章（共 %2 章）</translation>
    </message>
    <message>
        <source>the voice lost syllables of chapter %1</source>
        <translation>語音遺失了第 %1 章的音節</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>the text is empty: there is nothing to read</source>
        <translation>文字是空的：沒有可朗讀的內容</translation>
    </message>
    <message>
        <source>no sentence ends anywhere in the text: end its sentences with . ! ? or 。！？ so that the book can highlight them as they are read</source>
        <translation>文字中沒有任何句子結尾：請以 . ! ? 或 。！？ 結束句子，書才能在朗讀時標示它們</translation>
    </message>
    <message>
        <source>the book is too large for a ZIP archive (4 GiB, 65535 files)</source>
        <translation>書太大，無法放進 ZIP 封存檔（4 GiB、65535 個檔案）</translation>
    </message>
    <message>
        <source>cannot compress %1</source>
        <translation>無法壓縮 %1</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <source>the drawing is nested more than %1 levels deep</source>
        <translation>繪圖的巢狀層級超過 %1 層</translation>
    </message>
    <message>
        <source>cannot write %1: FFmpeg has no %2 encoder</source>
        <translation>無法寫入 %1：FFmpeg 沒有 %2 編碼器</translation>
    </message>
    <message>
        <source>unsupported size %1x%2 (%3 takes 2 to 8192 pixels a side)</source>
        <translation>不支援的尺寸 %1x%2（%3 每邊需 2 到 8192 像素）</translation>
    </message>
    <message>
        <source>cannot start the %1 encoder at %2x%3: %4</source>
        <translation>無法以 %2x%3 啟動 %1 編碼器：%4</translation>
    </message>
    <message>
        <source>cannot convert %1x%2 RGBA for %3</source>
        <translation>無法為 %3 轉換 %1x%2 的 RGBA</translation>
    </message>
    <message>
        <source>the start (%1 s) and duration (%2 s) must be 0 or more</source>
        <translation>開始（%1 秒）與長度（%2 秒）必須為 0 或以上</translation>
    </message>
    <message>
        <source>SVG and HTML play the whole animation; a start or duration needs a video or picture format</source>
        <translation>SVG 與 HTML 會播放整段動畫；開始或長度需要影片或圖片格式</translation>
    </message>
    <message>
        <source>the start (%1 s) is past the end of the animation (%2 s)</source>
        <translation>開始（%1 秒）已超過動畫結尾（%2 秒）</translation>
    </message>
    <message>
        <source>MP4 cannot be transparent: choose WebM, MOV, WebP, APNG, GIF or PNG frames, or a background colour or photo</source>
        <translation>MP4 無法透明：請選擇 WebM、MOV、WebP、APNG、GIF 或 PNG 影格，或選擇背景顏色或照片</translation>
    </message>
    <message>
        <source>SVG and HTML are drawn without a background; a background colour or photo needs a video or picture format</source>
        <translation>SVG 與 HTML 不繪製背景；背景顏色或照片需要影片或圖片格式</translation>
    </message>
    <message>
        <source>the background colour is not valid</source>
        <translation>背景顏色無效</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a background: give a colour (a name such as white, or #rrggbb), transparent, or an existing image file</source>
        <translation>「%1」不是背景：請給顏色（例如 white 這樣的名稱，或 #rrggbb）、transparent，或現有的影像檔</translation>
    </message>
    <message>
        <source>the %1 preset writes %2: name the output .%3</source>
        <translation>%1 預設會寫出 %2：請將輸出命名為 .%3</translation>
    </message>
    <message>
        <source>the clip is %1 s long, the %2 preset allows %3 s (%4 s too long): export a stretch of at most %3 s</source>
        <translation>片段長 %1 秒，%2 預設最多 %3 秒（超出 %4 秒）：請匯出最多 %3 秒的一段</translation>
    </message>
    <message>
        <source>at the lowest quality the file is %1 KB, the %2 preset allows %3 KB (%4 KB over): export a shorter stretch or a lower frame rate</source>
        <translation>即使最低畫質，檔案仍有 %1 KB，%2 預設最多 %3 KB（超出 %4 KB）：請匯出較短的一段或較低的影格率</translation>
    </message>
    <message>
        <source>cannot write: the GIF encoder wrote an unexpected file</source>
        <translation>無法寫入：GIF 編碼器寫出了非預期的檔案</translation>
    </message>
    <message>
        <source>cannot start the %1 encoder: %2</source>
        <translation>無法啟動 %1 編碼器：%2</translation>
    </message>
    <message>
        <source>no sound to cut the page&apos;s video from</source>
        <translation>沒有可剪出該頁影片的聲音</translation>
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
    <message>
        <source>WebM video (with transparency)</source>
        <translation>WebM 影片（含透明）</translation>
    </message>
    <message>
        <source>MOV ProRes 4444 (with transparency, for video editors)</source>
        <translation>MOV ProRes 4444（含透明，供影片剪輯軟體使用）</translation>
    </message>
    <message>
        <source>Animated PNG</source>
        <translation>動態 PNG</translation>
    </message>
    <message>
        <source>Animated WebP</source>
        <translation>動態 WebP</translation>
    </message>
    <message>
        <source>Telegram sticker (512 px, up to 3 s and 256 KB)</source>
        <translation>Telegram 貼圖（512 像素，最多 3 秒與 256 KB）</translation>
    </message>
    <message>
        <source>Emoji (100 px, up to 3 s and 64 KB)</source>
        <translation>表情符號（100 像素，最多 3 秒與 64 KB）</translation>
    </message>
    <message>
        <source>Slide overlay (1080 px, with sound)</source>
        <translation>簡報疊加（1080 像素，含聲音）</translation>
    </message>
    <message>
        <source>WebM video (*.webm)</source>
        <translation>WebM 影片 (*.webm)</translation>
    </message>
    <message>
        <source>MOV video (*.mov)</source>
        <translation>MOV 影片 (*.mov)</translation>
    </message>
    <message>
        <source>Animated PNG (*.apng)</source>
        <translation>動態 PNG (*.apng)</translation>
    </message>
    <message>
        <source>Animated WebP (*.webp)</source>
        <translation>動態 WebP (*.webp)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>無</translation>
    </message>
    <message>
        <source>Ready-made settings for a place where talking faces are shared; the export keeps to its limits or says why it cannot</source>
        <translation>為分享說話臉的地方準備好的設定；匯出會遵守其限制，或說明為何無法做到</translation>
    </message>
    <message>
        <source>Transparent</source>
        <translation>透明</translation>
    </message>
    <message>
        <source>Colour…</source>
        <translation>顏色…</translation>
    </message>
    <message>
        <source>Photo…</source>
        <translation>照片…</translation>
    </message>
    <message>
        <source>Automatic: transparent for WebM, MOV, APNG, WebP and PNG frames, white for MP4 and GIF</source>
        <translation>自動：WebM、MOV、APNG、WebP 與 PNG 影格為透明，MP4 與 GIF 為白色</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>To the end</source>
        <translation>到結尾</translation>
    </message>
    <message>
        <source>for</source>
        <translation>長度</translation>
    </message>
    <message>
        <source>&amp;Preset:</source>
        <translation>預設(&amp;P)：</translation>
    </message>
    <message>
        <source>&amp;Background:</source>
        <translation>背景(&amp;B)：</translation>
    </message>
    <message>
        <source>Fro&amp;m:</source>
        <translation>從(&amp;M)：</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>顏色：%1</translation>
    </message>
    <message>
        <source>Photo: %1</source>
        <translation>照片：%1</translation>
    </message>
    <message>
        <source>Background Colour</source>
        <translation>背景顏色</translation>
    </message>
    <message>
        <source>Background Photo</source>
        <translation>背景照片</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.webp *.bmp)</source>
        <translation>影像 (*.png *.jpg *.jpeg *.webp *.bmp)</translation>
    </message>
    <message>
        <source>cannot export: %1</source>
        <translation>無法匯出：%1</translation>
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
    <name>toonface::ImageFile</name>
    <message>
        <source>a WebP image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>這是 WebP 影像，此版本無法讀取；請轉換為 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a HEIC image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>這是 HEIC 影像，此版本無法讀取；請轉換為 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>an AVIF image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>這是 AVIF 影像，此版本無法讀取；請轉換為 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a TIFF image, which this build cannot read; convert it to PNG or JPEG</source>
        <translation>這是 TIFF 影像，此版本無法讀取；請轉換為 PNG 或 JPEG</translation>
    </message>
    <message>
        <source>a video or audio file (MP4/QuickTime), not a photo</source>
        <translation>這是影片或音訊檔案（MP4/QuickTime），不是照片</translation>
    </message>
    <message>
        <source>a WAV audio file, not a photo</source>
        <translation>這是 WAV 音訊檔案，不是照片</translation>
    </message>
    <message>
        <source>an audio file, not a photo</source>
        <translation>這是音訊檔案，不是照片</translation>
    </message>
    <message>
        <source>a PDF document, not an image</source>
        <translation>這是 PDF 文件，不是影像</translation>
    </message>
    <message>
        <source>a ZIP archive (or an office document), not an image</source>
        <translation>這是 ZIP 壓縮檔（或文書處理文件），不是影像</translation>
    </message>
    <message>
        <source>text, not an image (it starts with &quot;%1&quot;)</source>
        <translation>這是文字，不是影像（開頭為「%1」）</translation>
    </message>
    <message>
        <source>not an image (unrecognised data starting with %1)</source>
        <translation>不是影像（無法辨識的資料，開頭為 %1）</translation>
    </message>
    <message>
        <source>its %1 chunk claims %2 bytes, but only %3 are left in the file</source>
        <translation>其 %1 區塊聲稱有 %2 位元組，但檔案只剩 %3 位元組</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>檔案不存在</translation>
    </message>
    <message>
        <source>is a folder, not an image</source>
        <translation>這是資料夾，不是影像</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>檔案是空的</translation>
    </message>
    <message>
        <source>the file is too large for a photo (%1 MB)</source>
        <translation>檔案太大，不像是照片（%1 MB）</translation>
    </message>
    <message>
        <source>cannot read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <source>the JPEG image is truncated (the file ends before the image data does)</source>
        <translation>JPEG 影像不完整（檔案在影像資料結束前就結束了）</translation>
    </message>
    <message>
        <source>the PNG image is corrupt or truncated (%1)</source>
        <translation>PNG 影像已損壞或不完整（%1）</translation>
    </message>
    <message>
        <source>the %1 image is empty (%2 × %3 pixels)</source>
        <translation>%1 影像是空的（%2 × %3 像素）</translation>
    </message>
    <message>
        <source>the image is too large: %1 × %2 pixels (%3 megapixels); the limit is %4 megapixels</source>
        <translation>影像太大：%1 × %2 像素（%3 百萬像素）；上限為 %4 百萬像素</translation>
    </message>
    <message>
        <source>the %1 image is corrupt or truncated (%2)</source>
        <translation>%1 影像已損壞或不完整（%2）</translation>
    </message>
    <message>
        <source>cannot read layer file %1: %2</source>
        <translation>無法讀取圖層檔案 %1：%2</translation>
    </message>
    <message>
        <source>layer file %1 is not a valid SVG file: %2</source>
        <translation>圖層檔案 %1 不是有效的 SVG 檔案：%2</translation>
    </message>
    <message>
        <source>the root element is &lt;%1&gt;, not &lt;svg&gt;</source>
        <translation>根元素是 &lt;%1&gt;，不是 &lt;svg&gt;</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>第 %1 行第 %2 欄：%3</translation>
    </message>
    <message>
        <source>no root element</source>
        <translation>沒有根元素</translation>
    </message>
    <message>
        <source>elements nested more than %1 deep</source>
        <translation>元素巢狀超過 %1 層</translation>
    </message>
    <message>
        <source>more than %1 elements</source>
        <translation>超過 %1 個元素</translation>
    </message>
    <message>
        <source>the entity &amp;%1; is not defined</source>
        <translation>實體 &amp;%1; 未定義</translation>
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
    <message>
        <source>Use the clip&apos;s s&amp;ound (a new clip on the audio track)</source>
        <translation>使用片段的聲音（音軌上的新片段）(&amp;O)</translation>
    </message>
    <message>
        <source>It plays over %1: &amp;replace it (else both sound together)</source>
        <translation>會與 %1 重疊播放：取代它（否則兩者一起發聲）(&amp;R)</translation>
    </message>
    <message>
        <source>Looking for a frame at rest in the first seconds…</source>
        <translation>正在開頭幾秒中尋找靜止的影格…</translation>
    </message>
    <message>
        <source>No face was found in the first seconds: choose a frame that shows one.</source>
        <translation>開頭幾秒中找不到臉：請選一個有臉的影格。</translation>
    </message>
    <message>
        <source>mouth closed, eyes open, in a silence</source>
        <translation>嘴閉著、眼睜開、無人說話</translation>
    </message>
    <message>
        <source>mouth closed, eyes open</source>
        <translation>嘴閉著、眼睜開</translation>
    </message>
    <message>
        <source>Frame %1 looks at rest (%2); your choice is kept.</source>
        <translation>第 %1 影格看來是靜止的（%2）；保留您的選擇。</translation>
    </message>
    <message>
        <source>Frame %1 was chosen: %2. Pick another if it is not at rest.</source>
        <translation>已選第 %1 影格：%2。若不是靜止的，請另選一個。</translation>
    </message>
    <message>
        <source>Off: the project has a sound already (%1). Tick to add the clip&apos;s as well.</source>
        <translation>未勾選：專案已有聲音（%1）。勾選即可一併加入片段的聲音。</translation>
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
    <message>
        <source>Aligns a recording with the script it speaks, syllable by syllable. The recording becomes a clip on the audio track; the mouth keys and syllables where it plays are replaced, the other recordings and the rest of the timeline are kept.</source>
        <translation>逐音節將錄音與其文稿對齊。錄音成為音軌上的一個片段；其播放範圍內的口型關鍵影格與音節會被取代，其他錄音與時間軸的其餘部分都會保留。</translation>
    </message>
</context>
<context>
    <name>toonface::LipSyncFile</name>
    <message>
        <source>unexpected end of file, expected %1</source>
        <translation>檔案意外結束，應有%1</translation>
    </message>
    <message>
        <source>expected %1 (an integer of at least %2), found &apos;%3&apos;</source>
        <translation>應為%1（至少為 %2 的整數），實際為「%3」</translation>
    </message>
    <message>
        <source>%1: line %2: %3</source>
        <translation>%1：第 %2 行：%3</translation>
    </message>
    <message>
        <source>unknown mouth shape &apos;%1&apos; (known: %2)</source>
        <translation>未知的口型「%1」（已知：%2）</translation>
    </message>
    <message>
        <source>expected &apos;start&lt;TAB&gt;shape&apos;, found &apos;%1&apos;</source>
        <translation>應為「開始時間&lt;TAB&gt;口型」，實際為「%1」</translation>
    </message>
    <message>
        <source>expected a start time in seconds (a number of at least 0), found &apos;%1&apos;</source>
        <translation>應為以秒計的開始時間（至少為 0 的數字），實際為「%1」</translation>
    </message>
    <message>
        <source>time %1 is before the previous line&apos;s %2</source>
        <translation>時間 %1 早於上一行的 %2</translation>
    </message>
    <message>
        <source>%1: line %2: not valid JSON: %3</source>
        <translation>%1：第 %2 行：不是有效的 JSON：%3</translation>
    </message>
    <message>
        <source>expected a JSON object with mouthCues</source>
        <translation>應為含有 mouthCues 的 JSON 物件</translation>
    </message>
    <message>
        <source>%1: expected a duration of at least 0</source>
        <translation>%1：應為至少 0 的時長</translation>
    </message>
    <message>
        <source>%1: expected a time of at least 0</source>
        <translation>%1：應為至少 0 的時間</translation>
    </message>
    <message>
        <source>%1: ends (%2) before it starts (%3)</source>
        <translation>%1：結束時間（%2）早於開始時間（%3）</translation>
    </message>
    <message>
        <source>%1: starts (%2) before the previous cue ends (%3)</source>
        <translation>%1：開始時間（%2）早於上一個提示的結束時間（%3）</translation>
    </message>
    <message>
        <source>%1: unknown mouth shape &apos;%2&apos; (known: %3)</source>
        <translation>%1：未知的口型「%2」（已知：%3）</translation>
    </message>
    <message>
        <source>the header &apos;lipsync version 1&apos;</source>
        <translation>標頭「lipsync version 1」</translation>
    </message>
    <message>
        <source>expected the header &apos;lipsync version 1&apos;, found &apos;%1&apos;</source>
        <translation>應為標頭「lipsync version 1」，實際為「%1」</translation>
    </message>
    <message>
        <source>the sound file</source>
        <translation>聲音檔案</translation>
    </message>
    <message>
        <source>the frame rate</source>
        <translation>影格速率</translation>
    </message>
    <message>
        <source>the duration in frames</source>
        <translation>以影格計的時長</translation>
    </message>
    <message>
        <source>the number of voices</source>
        <translation>聲部數量</translation>
    </message>
    <message>
        <source>the voice&apos;s name</source>
        <translation>聲部名稱</translation>
    </message>
    <message>
        <source>the voice&apos;s text</source>
        <translation>聲部文字</translation>
    </message>
    <message>
        <source>the number of phrases</source>
        <translation>片語數量</translation>
    </message>
    <message>
        <source>the text of phrase %1</source>
        <translation>第 %1 個片語的文字</translation>
    </message>
    <message>
        <source>the start frame of phrase %1</source>
        <translation>第 %1 個片語的開始影格</translation>
    </message>
    <message>
        <source>the end frame of phrase %1</source>
        <translation>第 %1 個片語的結束影格</translation>
    </message>
    <message>
        <source>the number of words of phrase %1</source>
        <translation>第 %1 個片語的字詞數</translation>
    </message>
    <message>
        <source>word %1 of phrase %2 (&apos;text start end phonemes&apos;)</source>
        <translation>第 %2 個片語的第 %1 個字詞（「文字 開始 結束 音素數」）</translation>
    </message>
    <message>
        <source>expected %1, found &apos;%2&apos;</source>
        <translation>應為%1，實際為「%2」</translation>
    </message>
    <message>
        <source>the start frame of &apos;%1&apos;</source>
        <translation>「%1」的開始影格</translation>
    </message>
    <message>
        <source>the end frame of &apos;%1&apos;</source>
        <translation>「%1」的結束影格</translation>
    </message>
    <message>
        <source>the phoneme count of &apos;%1&apos;</source>
        <translation>「%1」的音素數</translation>
    </message>
    <message>
        <source>word &apos;%1&apos; ends (frame %2) before it starts (frame %3)</source>
        <translation>字詞「%1」的結束（第 %2 影格）早於開始（第 %3 影格）</translation>
    </message>
    <message>
        <source>phoneme %1 of &apos;%2&apos; (&apos;frame name&apos;)</source>
        <translation>「%2」的第 %1 個音素（「影格 名稱」）</translation>
    </message>
    <message>
        <source>the frame of a phoneme</source>
        <translation>音素的影格</translation>
    </message>
    <message>
        <source>phoneme frame %1 is before the previous phoneme&apos;s %2</source>
        <translation>音素影格 %1 早於上一個音素的 %2</translation>
    </message>
    <message>
        <source>the header &apos;MohoSwitch1&apos;</source>
        <translation>標頭「MohoSwitch1」</translation>
    </message>
    <message>
        <source>expected the header &apos;MohoSwitch1&apos;, found &apos;%1&apos;</source>
        <translation>應為標頭「MohoSwitch1」，實際為「%1」</translation>
    </message>
    <message>
        <source>expected &apos;frame shape&apos;, found &apos;%1&apos;</source>
        <translation>應為「影格 口型」，實際為「%1」</translation>
    </message>
    <message>
        <source>a frame number</source>
        <translation>影格編號</translation>
    </message>
    <message>
        <source>frame %1 is before the previous line&apos;s frame %2</source>
        <translation>第 %1 影格早於上一行的第 %2 影格</translation>
    </message>
    <message>
        <source>%1: cannot read at %2 frames per second</source>
        <translation>%1：無法以每秒 %2 影格讀取</translation>
    </message>
    <message>
        <source>%1: not saved: %2</source>
        <translation>%1：未儲存：%2</translation>
    </message>
    <message>
        <source>%1: unknown lip-sync format (expected .tsv, .json, .pgo or .dat)</source>
        <translation>%1：未知的唇形同步格式（應為 .tsv、.json、.pgo 或 .dat）</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：無法讀取：%2</translation>
    </message>
    <message>
        <source>no interval tier named &apos;%1&apos;</source>
        <translation>沒有名為「%1」的區間層</translation>
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
    <message>
        <source>Nothing was recorded: the microphone heard nothing.</source>
        <translation>沒有錄到任何內容：麥克風什麼也沒聽到。</translation>
    </message>
    <message>
        <source>Recorded %1 s of the microphone: the mouth, with its sound saved as %2</source>
        <translation>已錄製麥克風 %1 秒：嘴巴動作，聲音儲存為 %2</translation>
    </message>
    <message>
        <source>Recorded %1 s of the microphone: the mouth, no sound</source>
        <translation>已錄製麥克風 %1 秒：嘴巴動作，沒有聲音</translation>
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
        <source>Mouth from microphone</source>
        <translation>嘴巴跟隨麥克風</translation>
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
    <message>
        <source>Choose “Video file…” to perform from a clip, or “Microphone only” to speak for the cartoon.</source>
        <translation>選擇「影片檔案…」用影片片段表演，或選擇「僅麥克風」為卡通人物說話。</translation>
    </message>
    <message>
        <source>Choose a camera, a video file, or the microphone only.</source>
        <translation>請選擇攝影機、影片檔案或僅麥克風。</translation>
    </message>
    <message>
        <source>Microphone only (no camera)</source>
        <translation>僅麥克風（不用攝影機）</translation>
    </message>
    <message>
        <source>Microphone “%1”</source>
        <translation>麥克風「%1」</translation>
    </message>
    <message>
        <source>Listening to “%1”: speak, and the cartoon speaks with you</source>
        <translation>正在收聽「%1」：說話時，卡通人物會跟著你說</translation>
    </message>
    <message>
        <source>Start a camera, a clip or the microphone, with a face open, before recording.</source>
        <translation>錄製前請先開啟一張有臉的照片，並啟動攝影機、影片片段或麥克風。</translation>
    </message>
    <message>
        <source>Mouth from the lips in the picture</source>
        <translation>嘴巴跟隨畫面中的嘴唇</translation>
    </message>
    <message>
        <source>Lips in the picture, microphone when they are lost</source>
        <translation>畫面中的嘴唇，跟丟時用麥克風</translation>
    </message>
    <message>
        <source>What drives the cartoon&apos;s mouth: the lips the source shows, the loudness and colour of the voice, or both</source>
        <translation>驅動卡通嘴巴的來源：畫面中的嘴唇、聲音的大小與音色，或兩者並用</translation>
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
        <source> · control point</source>
        <translation> · 控制點</translation>
    </message>
    <message>
        <source> · placed by hand</source>
        <translation> · 手動放置</translation>
    </message>
    <message>
        <source>The cartoon made from %1 is not saved as a project yet. Save it?</source>
        <translation>由 %1 製作的卡通尚未儲存為專案。要儲存嗎？</translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes. Save them?</source>
        <translation>專案 %1 有尚未儲存的變更。要儲存嗎？</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵(&amp;K)</translation>
    </message>
    <message>
        <source>%1 at %2, %3</source>
        <translation>%1 位於 %2, %3</translation>
    </message>
    <message>
        <source>User &amp;Manual</source>
        <translation>使用手冊(&amp;M)</translation>
    </message>
</context>
<context>
    <name>toonface::ManualDialog</name>
    <message>
        <source>User Manual</source>
        <translation>使用手冊</translation>
    </message>
</context>
<context>
    <name>toonface::Media</name>
    <message>
        <source>the data is invalid or damaged</source>
        <translation>資料無效或已損壞</translation>
    </message>
    <message>
        <source>the file ends early</source>
        <translation>檔案提前結束</translation>
    </message>
    <message>
        <source>no decoder for it</source>
        <translation>沒有對應的解碼器</translation>
    </message>
    <message>
        <source>no encoder for it</source>
        <translation>沒有對應的編碼器</translation>
    </message>
    <message>
        <source>its format is not recognised</source>
        <translation>無法辨識其格式</translation>
    </message>
    <message>
        <source>the format cannot be written</source>
        <translation>無法寫入此格式</translation>
    </message>
    <message>
        <source>no such file or folder</source>
        <translation>檔案或資料夾不存在</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>權限不足</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>這是資料夾</translation>
    </message>
    <message>
        <source>the disk is full</source>
        <translation>磁碟已滿</translation>
    </message>
    <message>
        <source>the disk is read-only</source>
        <translation>磁碟為唯讀</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>記憶體不足</translation>
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
        <translation>在圖中拖曳嘴巴的四個點即可改變口型。每個口型適用於任何臉：它依這張臉的嘴巴比例移動嘴唇。</translation>
    </message>
    <message>
        <source>Ad&amp;vanced: the numbers</source>
        <translation>進階：數值(&amp;V)</translation>
    </message>
    <message>
        <source>× nose to mouth</source>
        <translation>× 鼻到嘴</translation>
    </message>
    <message>
        <source>× mouth width</source>
        <translation>× 嘴寬</translation>
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
        <translation>MW0：嘴巴的寬度，從嘴角到嘴角</translation>
    </message>
    <message>
        <source>LowerLipH: the height of the lower lip</source>
        <translation>LowerLipH：下唇的高度</translation>
    </message>
    <message>
        <source>ES0/100: a hundredth of the distance between the eyes</source>
        <translation>ES0/100：兩眼距離的百分之一</translation>
    </message>
    <message>
        <source>The move on this face, in pixels</source>
        <translation>在這張臉上移動的像素</translation>
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
    <message>
        <source>Hair outline, point %1</source>
        <comment>a point of the face</comment>
        <translation>髮際輪廓，第 %1 點</translation>
    </message>
    <message>
        <source>Left temple</source>
        <comment>a point of the face</comment>
        <translation>左太陽穴</translation>
    </message>
    <message>
        <source>Hairline, centre</source>
        <comment>a point of the face</comment>
        <translation>髮際線中央</translation>
    </message>
    <message>
        <source>Right temple</source>
        <comment>a point of the face</comment>
        <translation>右太陽穴</translation>
    </message>
    <message>
        <source>Left cheek</source>
        <comment>a point of the face</comment>
        <translation>左臉頰</translation>
    </message>
    <message>
        <source>Right cheek</source>
        <comment>a point of the face</comment>
        <translation>右臉頰</translation>
    </message>
    <message>
        <source>Jaw, left, at the mouth</source>
        <comment>a point of the face</comment>
        <translation>下顎左側，與嘴同高</translation>
    </message>
    <message>
        <source>Lower jaw, left</source>
        <comment>a point of the face</comment>
        <translation>下顎左下方</translation>
    </message>
    <message>
        <source>Chin</source>
        <comment>a point of the face</comment>
        <translation>下巴</translation>
    </message>
    <message>
        <source>Lower jaw, right</source>
        <comment>a point of the face</comment>
        <translation>下顎右下方</translation>
    </message>
    <message>
        <source>Jaw, right, at the mouth</source>
        <comment>a point of the face</comment>
        <translation>下顎右側，與嘴同高</translation>
    </message>
    <message>
        <source>Left ear, top</source>
        <comment>a point of the face</comment>
        <translation>左耳，頂端</translation>
    </message>
    <message>
        <source>Left ear, outermost point</source>
        <comment>a point of the face</comment>
        <translation>左耳，最外側</translation>
    </message>
    <message>
        <source>Left ear, bottom of the lobe</source>
        <comment>a point of the face</comment>
        <translation>左耳，耳垂底端</translation>
    </message>
    <message>
        <source>Left ear, where the lobe meets the cheek</source>
        <comment>a point of the face</comment>
        <translation>左耳，耳垂與臉頰交接處</translation>
    </message>
    <message>
        <source>Right ear, top</source>
        <comment>a point of the face</comment>
        <translation>右耳，頂端</translation>
    </message>
    <message>
        <source>Right ear, outermost point</source>
        <comment>a point of the face</comment>
        <translation>右耳，最外側</translation>
    </message>
    <message>
        <source>Right ear, bottom of the lobe</source>
        <comment>a point of the face</comment>
        <translation>右耳，耳垂底端</translation>
    </message>
    <message>
        <source>Right ear, where the lobe meets the cheek</source>
        <comment>a point of the face</comment>
        <translation>右耳，耳垂與臉頰交接處</translation>
    </message>
    <message>
        <source>Left eyebrow, outer end</source>
        <comment>a point of the face</comment>
        <translation>左眉，外端</translation>
    </message>
    <message>
        <source>Left eyebrow, outer arch</source>
        <comment>a point of the face</comment>
        <translation>左眉，外側眉峰</translation>
    </message>
    <message>
        <source>Left eyebrow, inner arch</source>
        <comment>a point of the face</comment>
        <translation>左眉，內側眉峰</translation>
    </message>
    <message>
        <source>Left eyebrow, inner end</source>
        <comment>a point of the face</comment>
        <translation>左眉，內端</translation>
    </message>
    <message>
        <source>Right eyebrow, inner end</source>
        <comment>a point of the face</comment>
        <translation>右眉，內端</translation>
    </message>
    <message>
        <source>Right eyebrow, inner arch</source>
        <comment>a point of the face</comment>
        <translation>右眉，內側眉峰</translation>
    </message>
    <message>
        <source>Right eyebrow, outer arch</source>
        <comment>a point of the face</comment>
        <translation>右眉，外側眉峰</translation>
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
        <translation>左眼，上眼瞼</translation>
    </message>
    <message>
        <source>Left eye, inner corner</source>
        <comment>a point of the face</comment>
        <translation>左眼，內眼角</translation>
    </message>
    <message>
        <source>Left eye, lower lid</source>
        <comment>a point of the face</comment>
        <translation>左眼，下眼瞼</translation>
    </message>
    <message>
        <source>Left eye, centre of the eyeball</source>
        <comment>a point of the face</comment>
        <translation>左眼，眼球中心</translation>
    </message>
    <message>
        <source>Right eye, inner corner</source>
        <comment>a point of the face</comment>
        <translation>右眼，內眼角</translation>
    </message>
    <message>
        <source>Right eye, upper lid</source>
        <comment>a point of the face</comment>
        <translation>右眼，上眼瞼</translation>
    </message>
    <message>
        <source>Right eye, outer corner</source>
        <comment>a point of the face</comment>
        <translation>右眼，外眼角</translation>
    </message>
    <message>
        <source>Right eye, lower lid</source>
        <comment>a point of the face</comment>
        <translation>右眼，下眼瞼</translation>
    </message>
    <message>
        <source>Right eye, centre of the eyeball</source>
        <comment>a point of the face</comment>
        <translation>右眼，眼球中心</translation>
    </message>
    <message>
        <source>Bridge of the nose, left</source>
        <comment>a point of the face</comment>
        <translation>鼻樑，左側</translation>
    </message>
    <message>
        <source>Bridge of the nose, right</source>
        <comment>a point of the face</comment>
        <translation>鼻樑，右側</translation>
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
        <translation>上唇，上緣中央</translation>
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
        <translation>下唇，下緣中央</translation>
    </message>
    <message>
        <source>Upper lip, inner edge</source>
        <comment>a point of the face</comment>
        <translation>上唇，內緣</translation>
    </message>
    <message>
        <source>Lower lip, inner edge</source>
        <comment>a point of the face</comment>
        <translation>下唇，內緣</translation>
    </message>
</context>
<context>
    <name>toonface::PhotoView</name>
    <message>
        <source>Another face in the photo: click to use it instead</source>
        <translation>照片中的另一張臉：按一下改用它</translation>
    </message>
    <message>
        <source>Open a photo of a face (%1), or drop one here.</source>
        <translation>開啟一張臉部相片（%1），或將相片拖放到這裡。</translation>
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
    <message>
        <source>&amp;Transparent Background</source>
        <translation>透明背景(&amp;T)</translation>
    </message>
    <message>
        <source>Show the cartoon without its background, over a checkerboard, as a transparent sticker exports it</source>
        <translation>把卡通畫在棋盤格上、不含背景，就像匯出的透明貼圖</translation>
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
        <translation>應為數字</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>應為字串</translation>
    </message>
    <message>
        <source>must not be negative</source>
        <translation>不可為負數</translation>
    </message>
    <message>
        <source>must be positive</source>
        <translation>必須為正數</translation>
    </message>
    <message>
        <source>must be between 0 and 1</source>
        <translation>必須介於 0 與 1 之間</translation>
    </message>
    <message>
        <source>%1: expected an array</source>
        <translation>%1：應為陣列</translation>
    </message>
    <message>
        <source>%1: expected an object</source>
        <translation>%1：應為物件</translation>
    </message>
    <message>
        <source>expected a positive integer</source>
        <translation>應為正整數</translation>
    </message>
    <message>
        <source>%1 is newer than this Toonface reads (%2)</source>
        <translation>%1 比這個 Toonface 能讀取的版本（%2）更新</translation>
    </message>
    <message>
        <source>smoothing: expected an object</source>
        <translation>smoothing：應為物件</translation>
    </message>
    <message>
        <source>unknown mouth shape &apos;%1&apos;</source>
        <translation>未知的口型「%1」</translation>
    </message>
    <message>
        <source>must not be before start</source>
        <translation>不可早於 start</translation>
    </message>
    <message>
        <source>unknown emotion &apos;%1&apos;</source>
        <translation>未知的表情「%1」</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>應為物件</translation>
    </message>
    <message>
        <source>unknown point ID</source>
        <translation>未知的特徵點 ID</translation>
    </message>
    <message>
        <source>expected [dx, dy], two numbers</source>
        <translation>應為 [dx, dy] 兩個數字</translation>
    </message>
    <message>
        <source>video: expected an object</source>
        <translation>video：應為物件</translation>
    </message>
    <message>
        <source>an [x, y] pair</source>
        <translation>一組 [x, y]</translation>
    </message>
    <message>
        <source>a box of negative size</source>
        <translation>方框的尺寸為負數</translation>
    </message>
    <message>
        <source>two boxes, image-left first</source>
        <translation>兩個方框，影像左側的在前</translation>
    </message>
    <message>
        <source>two eyeballs, image-left first</source>
        <translation>兩顆眼球，影像左側的在前</translation>
    </message>
    <message>
        <source>four edge thresholds, top part first</source>
        <translation>四個邊緣閾值，上半部的在前</translation>
    </message>
    <message>
        <source>%1 was made by a newer Toonface (this version reads %2)</source>
        <translation>%1 是由較新版的 Toonface 建立的（此版本讀取 %2）</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>數字</translation>
    </message>
    <message>
        <source>a finite number</source>
        <translation>有限的數字</translation>
    </message>
    <message>
        <source>a number between %1 and %2</source>
        <translation>介於 %1 與 %2 之間的數字</translation>
    </message>
    <message>
        <source>an integer from %1 to %2</source>
        <translation>%1 到 %2 的整數</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>a string</source>
        <translation>字串</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>an array</source>
        <translation>陣列</translation>
    </message>
    <message>
        <source>expected %1, %2</source>
        <translation>應為%1，%2</translation>
    </message>
    <message>
        <source>it is missing</source>
        <translation>但缺少此項</translation>
    </message>
    <message>
        <source>found null</source>
        <translation>實際為 null</translation>
    </message>
    <message>
        <source>found true</source>
        <translation>實際為 true</translation>
    </message>
    <message>
        <source>found false</source>
        <translation>實際為 false</translation>
    </message>
    <message>
        <source>found %1</source>
        <translation>實際為 %1</translation>
    </message>
    <message>
        <source>found the string &quot;%1&quot;</source>
        <translation>實際為字串「%1」</translation>
    </message>
    <message>
        <source>found an array</source>
        <translation>實際為陣列</translation>
    </message>
    <message>
        <source>found an object</source>
        <translation>實際為物件</translation>
    </message>
    <message>
        <source>a width more than 0</source>
        <translation>大於 0 的寬度</translation>
    </message>
    <message>
        <source>not an SVG drawing: %1</source>
        <translation>不是 SVG 繪圖：%1</translation>
    </message>
    <message>
        <source>one of %1</source>
        <translation>下列之一：%1</translation>
    </message>
    <message>
        <source>a colour like #rrggbb or #aarrggbb, or &quot;none&quot;</source>
        <translation>#rrggbb 或 #aarrggbb 形式的顏色，或「none」</translation>
    </message>
    <message>
        <source>a number from 0 to %1</source>
        <translation>0 到 %1 的數字</translation>
    </message>
    <message>
        <source>a component needs a name</source>
        <translation>元件需要名稱</translation>
    </message>
    <message>
        <source>a width of 0 or more</source>
        <translation>0 或以上的寬度</translation>
    </message>
    <message>
        <source>unknown mouth shape (the shapes are %1)</source>
        <translation>未知的口型（口型有 %1）</translation>
    </message>
    <message>
        <source>not a Toonface project (it has no &quot;format&quot; field)</source>
        <translation>不是 Toonface 專案（沒有「format」欄位）</translation>
    </message>
    <message>
        <source>not a Toonface project (format: expected &quot;%1&quot;, %2)</source>
        <translation>不是 Toonface 專案（format：應為「%1」，%2）</translation>
    </message>
    <message>
        <source>a version number (1 or more)</source>
        <translation>版本號（1 或以上）</translation>
    </message>
    <message>
        <source>made by a newer Toonface (project version %1; this version reads up to %2)</source>
        <translation>由較新版的 Toonface 建立（專案版本 %1；此版本最多讀取到 %2）</translation>
    </message>
    <message>
        <source>a file path</source>
        <translation>檔案路徑</translation>
    </message>
    <message>
        <source>not saved: the project is invalid at %1</source>
        <translation>未儲存：專案在 %1 處無效</translation>
    </message>
    <message>
        <source>cannot save: %1</source>
        <translation>無法儲存：%1</translation>
    </message>
    <message>
        <source>only %1 of %2 bytes could be written (is the disk full?)</source>
        <translation>%2 位元組中只寫入了 %1 位元組（磁碟是否已滿？）</translation>
    </message>
    <message>
        <source>the file could not be completed (is the disk full?)</source>
        <translation>無法完成檔案（磁碟是否已滿？）</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>檔案不存在</translation>
    </message>
    <message>
        <source>is a folder, not a Toonface project</source>
        <translation>這是資料夾，不是 Toonface 專案</translation>
    </message>
    <message>
        <source>too large to be a Toonface project (%1 MB)</source>
        <translation>檔案太大，不可能是 Toonface 專案（%1 MB）</translation>
    </message>
    <message>
        <source>cannot read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <source>the file is empty, not a Toonface project</source>
        <translation>檔案是空的，不是 Toonface 專案</translation>
    </message>
    <message>
        <source>not a Toonface project: %1 at offset %2 (line %3, column %4)</source>
        <translation>不是 Toonface 專案：位移 %2 處%1（第 %3 行第 %4 欄）</translation>
    </message>
    <message>
        <source>not a Toonface project (expected a JSON object, found an array)</source>
        <translation>不是 Toonface 專案（應為 JSON 物件，實際為陣列）</translation>
    </message>
    <message>
        <source>%1 s is outside the syllable (%2 to %3 s) or before the shape before it</source>
        <translation>%1 秒超出音節範圍（%2 到 %3 秒），或早於前一個口型</translation>
    </message>
    <message>
        <source>a time of 0 s or more</source>
        <translation>0 秒或以上的時間</translation>
    </message>
    <message>
        <source>a time after the start (%1 s)</source>
        <translation>開始時間（%1 秒）之後的時間</translation>
    </message>
    <message>
        <source>expected %1 points, found %2</source>
        <translation>應有 %1 個點，實際有 %2 個</translation>
    </message>
    <message>
        <source>&quot;cmn&quot;, &quot;en&quot; or &quot;&quot;</source>
        <translation>「cmn」、「en」或「」</translation>
    </message>
    <message>
        <source>%1 s is beyond the longest timeline Toonface keeps (%2 hours)</source>
        <translation>%1 秒超出 Toonface 時間軸的最長長度（%2 小時）</translation>
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
        <translation>聲音</translation>
    </message>
    <message>
        <source>video</source>
        <translation>影片</translation>
    </message>
    <message>
        <source>layer</source>
        <translation>圖層</translation>
    </message>
    <message>
        <source>is a folder, not a file</source>
        <translation>是資料夾，不是檔案</translation>
    </message>
    <message>
        <source>is a device, a pipe or a socket, not a file</source>
        <translation>是裝置、管道或通訊端，不是檔案</translation>
    </message>
    <message>
        <source>too large (more than %1 MB)</source>
        <translation>太大（超過 %1 MB）</translation>
    </message>
    <message>
        <source>no space left on the disk (%1 KB free on %2)</source>
        <translation>磁碟已無空間（%2 上只剩 %1 KB）</translation>
    </message>
    <message>
        <source>the system gave no reason (is the disk full or removed?)</source>
        <translation>系統未說明原因（磁碟是否已滿或已移除？）</translation>
    </message>
    <message>
        <source>the trims are longer than the recording</source>
        <translation>修剪的長度超過錄音本身</translation>
    </message>
    <message>
        <source>the clip ends beyond the longest timeline Toonface keeps (%1 hours)</source>
        <translation>片段的結尾超出 Toonface 所能保存的最長時間軸（%1 小時）</translation>
    </message>
    <message>
        <source>expected &quot;cmn&quot;, &quot;en&quot; or &quot;&quot;</source>
        <translation>應為 &quot;cmn&quot;、&quot;en&quot; 或 &quot;&quot;</translation>
    </message>
    <message>
        <source>audio: expected an array of clips</source>
        <translation>audio：應為片段的陣列</translation>
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
    <message>
        <source>Files Outside the Project</source>
        <translation>專案資料夾以外的檔案</translation>
    </message>
    <message>
        <source>%1 uses files outside its folder. Its sound, photo, video and layers are read from there when you play or export it:</source>
        <translation>%1 使用了其資料夾以外的檔案。播放或匯出時，會從這些位置讀取它的聲音、照片、影片和圖層：</translation>
    </message>
    <message>
        <source>Project Changed on Disk</source>
        <translation>專案已在磁碟上變更</translation>
    </message>
    <message>
        <source>%1 was changed by another program since you opened it.</source>
        <translation>自您開啟後，%1 已被其他程式變更。</translation>
    </message>
    <message>
        <source>Overwriting it loses the other program&apos;s changes.</source>
        <translation>覆寫會遺失其他程式所做的變更。</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存新檔(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Overwrite</source>
        <translation>覆寫(&amp;O)</translation>
    </message>
    <message>
        <source>Re-detect Points</source>
        <translation>重新偵測特徵點</translation>
    </message>
    <message numerus="yes">
        <source>You moved %n point(s) by hand. Re-detecting replaces every point.</source>
        <translation>
            <numerusform>您手動移動了 %n 個特徵點。重新偵測會取代所有特徵點。</numerusform>
        </translation>
    </message>
    <message>
        <source>Keep the points you moved, or replace them with the detected ones?</source>
        <translation>要保留您移動的特徵點，還是以偵測到的特徵點取代？</translation>
    </message>
    <message>
        <source>&amp;Keep My Points</source>
        <translation>保留我的特徵點(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;Replace Them</source>
        <translation>取代它們(&amp;R)</translation>
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
    <message>
        <source>The built-in voice speaks the text and the face says it with the voice&apos;s exact timings. The speech becomes a clip on the audio track; the mouth keys and syllables where it plays are replaced, the other recordings are kept.</source>
        <translation>內建語音朗讀文字，臉部依語音的精確時間說出。語音成為音軌上的一個片段；其播放範圍內的口型關鍵影格與音節會被取代，其他錄音都會保留。</translation>
    </message>
</context>
<context>
    <name>toonface::Script</name>
    <message>
        <source>no reference rendering of the script</source>
        <translation>沒有文稿的參考朗讀</translation>
    </message>
    <message>
        <source>no speech found in the audio</source>
        <translation>音訊中找不到說話聲</translation>
    </message>
    <message>
        <source>the script is far too long for the audio: its %1 syllables need about %2 s of speech, the audio holds %3 s</source>
        <translation>文稿對這段音訊來說太長：%1 個音節約需 %2 秒的語音，音訊只有 %3 秒</translation>
    </message>
    <message>
        <source>the audio holds far more speech (%1 s) than the script&apos;s %2 syllables (about %3 s)</source>
        <translation>音訊中的語音（%1 秒）遠多於文稿的 %2 個音節（約 %3 秒）</translation>
    </message>
    <message>
        <source>the audio and the script could not be matched</source>
        <translation>無法將音訊與文稿對應</translation>
    </message>
    <message>
        <source>the script is empty</source>
        <translation>文稿是空的</translation>
    </message>
    <message>
        <source>the audio is empty</source>
        <translation>音訊是空的</translation>
    </message>
    <message>
        <source>%1 and %2 could not be aligned: %3</source>
        <translation>無法對齊 %1 與 %2：%3</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>無法讀取 %1</translation>
    </message>
    <message>
        <source>cannot start bzip2 decompression of %1</source>
        <translation>無法開始以 bzip2 解壓縮 %1</translation>
    </message>
    <message>
        <source>%1 is not a valid bzip2 file</source>
        <translation>%1 不是有效的 bzip2 檔案</translation>
    </message>
    <message>
        <source>Chinese character readings are missing (%1; install the Debian package unicode-data)</source>
        <translation>缺少漢字讀音（%1；請安裝 Debian 套件 unicode-data）</translation>
    </message>
    <message>
        <source>%1 holds no Mandarin readings</source>
        <translation>%1 中沒有華語讀音</translation>
    </message>
    <message>
        <source>the phrase dictionary %1 is missing (install the Debian package rime-data-terra-pinyin)</source>
        <translation>缺少詞語字典 %1（請安裝 Debian 套件 rime-data-terra-pinyin）</translation>
    </message>
    <message>
        <source>%1: built from other sources</source>
        <translation>%1：由其他來源建立</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
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
        <translation>拼音索引格式為 %1，應為 %2</translation>
    </message>
    <message>
        <source>pinyin index of %1 bytes, its header describes %2</source>
        <translation>拼音索引有 %1 位元組，但標頭記載 %2</translation>
    </message>
    <message>
        <source>pinyin index checksum mismatch (damaged)</source>
        <translation>拼音索引檢查碼不符（已損壞）</translation>
    </message>
    <message>
        <source>pinyin index has a bad syllable &apos;%1&apos;</source>
        <translation>拼音索引中有錯誤的音節「%1」</translation>
    </message>
    <message>
        <source>pinyin index syllable table is damaged</source>
        <translation>拼音索引的音節表已損壞</translation>
    </message>
    <message>
        <source>pinyin index character table is damaged</source>
        <translation>拼音索引的字元表已損壞</translation>
    </message>
    <message>
        <source>pinyin index character readings are damaged</source>
        <translation>拼音索引的字元讀音已損壞</translation>
    </message>
    <message>
        <source>pinyin index phrase table is damaged</source>
        <translation>拼音索引的詞語表已損壞</translation>
    </message>
    <message>
        <source>pinyin index phrase readings are damaged</source>
        <translation>拼音索引的詞語讀音已損壞</translation>
    </message>
    <message>
        <source>cannot be spoken</source>
        <translation>無法朗讀</translation>
    </message>
    <message>
        <source>is not English</source>
        <translation>不是英文</translation>
    </message>
    <message>
        <source>has no Mandarin reading in the dictionary</source>
        <translation>在字典中沒有華語讀音</translation>
    </message>
    <message>
        <source>is not valid Zhuyin</source>
        <translation>不是有效的注音</translation>
    </message>
    <message>
        <source>is a number: write it in characters or pinyin</source>
        <translation>是數字：請用漢字或拼音書寫</translation>
    </message>
    <message>
        <source>is not Hanyu pinyin</source>
        <translation>不是漢語拼音</translation>
    </message>
    <message>
        <source>line %1, column %2: &apos;%3&apos; %4</source>
        <translation>第 %1 行第 %2 欄：「%3」%4</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1（另有 %n 處）</numerusform>
        </translation>
    </message>
    <message>
        <source>the script holds nothing to speak</source>
        <translation>文稿中沒有可朗讀的內容</translation>
    </message>
    <message>
        <source>cannot read the script %1: %2</source>
        <translation>無法讀取文稿 %1：%2</translation>
    </message>
    <message>
        <source>the script %1 is not UTF-8 text</source>
        <translation>文稿 %1 不是 UTF-8 文字</translation>
    </message>
    <message>
        <source>espeak-ng cannot start: its data is missing (install espeak-ng-data)</source>
        <translation>espeak-ng 無法啟動：缺少資料（請安裝 espeak-ng-data）</translation>
    </message>
    <message>
        <source>nothing to speak</source>
        <translation>沒有可朗讀的內容</translation>
    </message>
    <message>
        <source>espeak-ng has no voice &apos;%1&apos;</source>
        <translation>espeak-ng 沒有「%1」語音</translation>
    </message>
    <message>
        <source>espeak-ng could not speak the script</source>
        <translation>espeak-ng 無法朗讀文稿</translation>
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
        <translation>口型 %1（按鍵 %2）：取代所選的口型關鍵影格，或在播放頭處插入一個</translation>
    </message>
</context>
<context>
    <name>toonface::ShortcutsDialog</name>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按鍵</translation>
    </message>
    <message>
        <source>Timeline (while it has focus)</source>
        <translation>時間軸（取得焦點時）</translation>
    </message>
    <message>
        <source>Set or insert a mouth shape</source>
        <translation>設定或插入口型</translation>
    </message>
    <message>
        <source>Zoom in, out, to fit</source>
        <translation>放大、縮小、縮放至適合</translation>
    </message>
    <message>
        <source>Zoom about the pointer</source>
        <translation>以指標為中心縮放</translation>
    </message>
    <message>
        <source>Ctrl+wheel</source>
        <translation>Ctrl+滾輪</translation>
    </message>
    <message>
        <source>Scroll the rows</source>
        <translation>捲動各列</translation>
    </message>
    <message>
        <source>Shift+wheel</source>
        <translation>Shift+滾輪</translation>
    </message>
    <message>
        <source>Waveform taller or shorter</source>
        <translation>波形加高或減低</translation>
    </message>
    <message>
        <source>Alt+wheel</source>
        <translation>Alt+滾輪</translation>
    </message>
    <message>
        <source>Edit a syllable&apos;s pinyin</source>
        <translation>編輯音節的拼音</translation>
    </message>
    <message>
        <source>Double-click</source>
        <translation>按兩下</translation>
    </message>
</context>
<context>
    <name>toonface::SoundFile</name>
    <message>
        <source>cannot read the audio: %1</source>
        <translation>無法讀取音訊：%1</translation>
    </message>
    <message>
        <source>no audio stream</source>
        <translation>沒有音訊串流</translation>
    </message>
    <message>
        <source>audio samples</source>
        <translation>音訊取樣</translation>
    </message>
    <message>
        <source>invalid sample rate %1</source>
        <translation>無效的取樣率 %1</translation>
    </message>
    <message>
        <source>the audio has no sample rate</source>
        <translation>音訊沒有取樣率</translation>
    </message>
    <message>
        <source>cannot resample the audio: %1</source>
        <translation>無法重新取樣音訊：%1</translation>
    </message>
    <message>
        <source>cannot decode the audio: %1</source>
        <translation>無法解碼音訊：%1</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>檔案是空的</translation>
    </message>
    <message>
        <source>not a readable sound or video file (%1)</source>
        <translation>不是可讀取的聲音或影片檔案（%1）</translation>
    </message>
    <message>
        <source>cannot read its streams (%1)</source>
        <translation>無法讀取其中的串流（%1）</translation>
    </message>
    <message>
        <source>no decoder for its sound track</source>
        <translation>沒有可解碼其音軌的解碼器</translation>
    </message>
    <message>
        <source>it has no sound track</source>
        <translation>其中沒有音軌</translation>
    </message>
    <message>
        <source>cannot open the %1 decoder</source>
        <translation>無法開啟 %1 解碼器</translation>
    </message>
    <message>
        <source>cannot convert its samples</source>
        <translation>無法轉換其取樣</translation>
    </message>
    <message>
        <source>its sound track cannot be decoded (corrupt data)</source>
        <translation>其音軌無法解碼（資料損壞）</translation>
    </message>
    <message>
        <source>it holds no sound</source>
        <translation>其中沒有聲音</translation>
    </message>
    <message>
        <source>it is silent (peak %1 dBFS)</source>
        <translation>是靜音的（峰值 %1 dBFS）</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>unknown sound format &apos;.%1&apos; (use wav, flac, mp3, ogg, opus or m4a)</source>
        <translation>未知的聲音格式「.%1」（請使用 wav、flac、mp3、ogg、opus 或 m4a）</translation>
    </message>
    <message>
        <source>this FFmpeg has no encoder for .%1</source>
        <translation>此 FFmpeg 沒有 .%1 的編碼器</translation>
    </message>
    <message>
        <source>no container for .%1</source>
        <translation>沒有 .%1 的容器格式</translation>
    </message>
    <message>
        <source>cannot open the %1 encoder (%2)</source>
        <translation>無法開啟 %1 編碼器（%2）</translation>
    </message>
    <message>
        <source>cannot add a sound stream</source>
        <translation>無法加入聲音串流</translation>
    </message>
    <message>
        <source>cannot convert the samples</source>
        <translation>無法轉換取樣</translation>
    </message>
    <message>
        <source>encoding failed</source>
        <translation>編碼失敗</translation>
    </message>
    <message>
        <source>its sample rate (%1 Hz) is too low for speech (at least %2 Hz)</source>
        <translation>其取樣率（%1 Hz）太低，不足以承載語音（至少需要 %2 Hz）</translation>
    </message>
    <message>
        <source>it is damaged: it decodes to more than %1 s of sound, more than its %2 bytes can hold</source>
        <translation>檔案已損壞：解碼出超過 %1 秒的聲音，超出其 %2 位元組所能容納的長度</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>holds no sound</source>
        <translation>沒有聲音</translation>
    </message>
    <message>
        <source>no room for a temporary copy of the sound: %1</source>
        <translation>沒有空間存放聲音的暫存副本：%1</translation>
    </message>
    <message>
        <source>the sound cannot be used: %1</source>
        <translation>無法使用這個聲音：%1</translation>
    </message>
    <message>
        <source>cut short (its header promises %1 s, it holds %2 s)</source>
        <translation>檔案不完整（標頭記載 %1 秒，實際只有 %2 秒）</translation>
    </message>
    <message>
        <source>the sound of several or trimmed recordings can only be embedded, not referenced</source>
        <translation>多段或經修剪的錄音只能內嵌，不能以參照方式使用</translation>
    </message>
    <message>
        <source>the writer is closed</source>
        <translation>寫入器已關閉</translation>
    </message>
    <message>
        <source>no samples in %1 packets</source>
        <translation>%1 個封包中沒有任何樣本</translation>
    </message>
    <message>
        <source>the sound does not decode at %1 s: %2</source>
        <translation>聲音在 %1 秒處無法解碼：%2</translation>
    </message>
    <message>
        <source>too long for a WAV file</source>
        <translation>對 WAV 檔案來說太長</translation>
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
    <message>
        <source>Place it after them</source>
        <translation>放在它們之後</translation>
    </message>
    <message>
        <source>Replace them (with their syllables and mouth keys)</source>
        <translation>取代它們（連同其音節與口型關鍵影格）</translation>
    </message>
    <message>
        <source>The timeline keeps every recording as a clip on the audio track. What to do when the new one would play over others: nothing is replaced unless you choose so.</source>
        <translation>時間軸將每段錄音保存為音軌上的片段。新錄音會與其他錄音重疊時的做法：除非您選擇取代，否則不會取代任何錄音。</translation>
    </message>
    <message>
        <source>If other recordings &amp;play there:</source>
        <translation>若該處已有其他錄音(&amp;P)：</translation>
    </message>
    <message>
        <source>%1 (%2 s) does not fit on the timeline there: it would end past %3 hours.</source>
        <translation>%1（%2 秒）放不進時間軸的該處：結尾會超過 %3 小時。</translation>
    </message>
    <message>
        <source>%1: %2 at %3 s</source>
        <translation>%1：%2 位於 %3 秒</translation>
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
    <message>
        <source>Imported %1 with its sound as a clip on the audio track</source>
        <translation>已匯入 %1，其聲音成為音軌上的片段</translation>
    </message>
</context>
<context>
    <name>toonface::TimeReadout</name>
    <message>
        <source>The playhead&apos;s time and frame</source>
        <translation>播放頭的時間與影格</translation>
    </message>
    <message>
        <source>%1:%2.%3  frame %4 / %5</source>
        <translation>%1:%2.%3  影格 %4 / %5</translation>
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
    <message>
        <source>Taller Waveform</source>
        <translation>加高波形</translation>
    </message>
    <message>
        <source>Shorter Waveform</source>
        <translation>減低波形</translation>
    </message>
    <message>
        <source> (Alt+wheel)</source>
        <translation>（Alt+滾輪）</translation>
    </message>
    <message>
        <source>Emotion Intensity</source>
        <translation>表情強度</translation>
    </message>
    <message>
        <source>Intensity of %1 (%):</source>
        <translation>%1的強度（%）：</translation>
    </message>
    <message>
        <source>Intensity…</source>
        <translation>強度…</translation>
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
    <name>toonface::VideoFile</name>
    <message>
        <source>no decoder for its %1 codec &apos;%2&apos;</source>
        <translation>沒有其 %1 編解碼器「%2」的解碼器</translation>
    </message>
    <message>
        <source>cannot open its %1 decoder: %2</source>
        <translation>無法開啟其 %1 解碼器：%2</translation>
    </message>
    <message>
        <source>no frame_NNNNN.png files in the folder</source>
        <translation>資料夾中沒有 frame_NNNNN.png 檔案</translation>
    </message>
    <message>
        <source>cannot read the streams: %1</source>
        <translation>無法讀取串流：%1</translation>
    </message>
    <message>
        <source>no video or audio stream</source>
        <translation>沒有影片或音訊串流</translation>
    </message>
    <message>
        <source>no video stream</source>
        <translation>沒有影片串流</translation>
    </message>
    <message>
        <source>has no frame %1 (it has %2)</source>
        <translation>沒有第 %1 影格（共有 %2 個）</translation>
    </message>
    <message>
        <source>invalid sample rate %1</source>
        <translation>無效的取樣率 %1</translation>
    </message>
    <message>
        <source>the neutral face&apos;s detection kept no tracking seed (thresholds, eyeballs, mouth region) for the classic method</source>
        <translation>中性臉的偵測沒有保留經典方法所需的追蹤種子（閾值、眼球、嘴巴區域）</translation>
    </message>
    <message>
        <source>%1: no face in any frame</source>
        <translation>%1：沒有任何影格含有臉部</translation>
    </message>
    <message>
        <source>the neutral frame is empty</source>
        <translation>中性影格是空的</translation>
    </message>
    <message>
        <source>the %1 tracking cannot follow the face it detected on the neutral frame</source>
        <translation>%1 追蹤無法跟隨在中性影格上偵測到的臉部</translation>
    </message>
    <message>
        <source>%1: tracking was cancelled</source>
        <translation>%1：追蹤已取消</translation>
    </message>
    <message>
        <source>%1: the neutral frame must be 0 or later</source>
        <translation>%1：中性影格必須為 0 或之後</translation>
    </message>
    <message>
        <source>%1: no video frame could be decoded</source>
        <translation>%1：沒有任何影格能夠解碼</translation>
    </message>
    <message>
        <source>%1: the neutral frame %2 is past the video&apos;s end (it has %3 frames)</source>
        <translation>%1：中性影格 %2 超出影片結尾（影片共有 %3 個影格）</translation>
    </message>
    <message>
        <source>%1: frame %2: %3</source>
        <translation>%1：第 %2 影格：%3</translation>
    </message>
    <message>
        <source>%1 (tracked the %2 frames before)</source>
        <translation>%1（已追蹤之前的 %2 個影格）</translation>
    </message>
    <message>
        <source>%1: %2 damaged packets were skipped; the frames around them may be wrong</source>
        <translation>%1：略過了 %2 個損壞的封包；附近的影格可能有誤</translation>
    </message>
    <message>
        <source>%1: the face was lost in %2 of %3 frames (they hold the last pose)</source>
        <translation>%1：%3 個影格中有 %2 個跟丟了臉部（這些影格保留最後的姿勢）</translation>
    </message>
    <message>
        <source>%1: the video cannot be decoded (%2)</source>
        <translation>%1：影片無法解碼（%2）</translation>
    </message>
    <message>
        <source>%1: cannot convert the video&apos;s pixel format</source>
        <translation>%1：無法轉換影片的像素格式</translation>
    </message>
    <message>
        <source>%1: out of memory</source>
        <translation>%1：記憶體不足</translation>
    </message>
    <message>
        <source>not a video FFmpeg can read (%1)</source>
        <translation>不是 FFmpeg 能讀取的影片（%1）</translation>
    </message>
    <message>
        <source>the file holds no video</source>
        <translation>檔案中沒有影片</translation>
    </message>
    <message>
        <source>cannot set up the video decoder</source>
        <translation>無法設定影片解碼器</translation>
    </message>
    <message>
        <source>cannot open the video decoder (%1)</source>
        <translation>無法開啟影片解碼器（%1）</translation>
    </message>
    <message>
        <source>the video has no picture size</source>
        <translation>影片沒有畫面尺寸</translation>
    </message>
    <message>
        <source>out of memory</source>
        <translation>記憶體不足</translation>
    </message>
    <message>
        <source>the file is cut short or damaged: its data breaks off at %1 s</source>
        <translation>檔案不完整或已損壞：資料在 %1 秒處中斷</translation>
    </message>
    <message>
        <source>the file is cut short or damaged: %1</source>
        <translation>檔案不完整或已損壞：%1</translation>
    </message>
    <message>
        <source>not a readable sound or video file (%1)</source>
        <translation>不是可讀取的聲音或影片檔案（%1）</translation>
    </message>
    <message>
        <source>%1: its sound could not be read (%2): the mouth is not closed in its silences</source>
        <translation>%1：無法讀取其聲音（%2）：靜音處的嘴不會閉上</translation>
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
    <name>toonface::WindowLayout</name>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>重設版面配置(&amp;R)</translation>
    </message>
    <message>
        <source>Put the panels back where they were at first and size them to the window</source>
        <translation>將各面板放回最初的位置，並依視窗調整大小</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>外觀</translation>
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
        <source>A photo or a project; or a video clip, whose neutral frame&apos;s face it animates.</source>
        <translation>照片或專案；或影片片段，以其中性影格的臉製作動畫。</translation>
    </message>
    <message>
        <source>animate takes one photo or project (usage: toonface-cli %1)</source>
        <translation>animate 只接受一張照片或一個專案（用法：toonface-cli %1）</translation>
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
        <source>Expression: neutral, smile, sad, angry or surprise (default: the face as photographed).</source>
        <translation>表情：neutral、smile、sad、angry 或 surprise（預設：照片中的臉）。</translation>
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
    <message>
        <source>%1: interrupted; nothing was written</source>
        <translation>%1：已中斷；未寫入任何內容</translation>
    </message>
    <message>
        <source>The recording of the whole text, headings included, in reading order.</source>
        <translation>整段文字的錄音，包括標題，依閱讀順序。</translation>
    </message>
    <message>
        <source>Read the text with the built-in voice.</source>
        <translation>以內建語音朗讀文字。</translation>
    </message>
    <message>
        <source>The face that reads: a photo or a project (default: an average face).</source>
        <translation>朗讀的臉：照片或專案（預設：平均臉）。</translation>
    </message>
    <message>
        <source>The book&apos;s language: %1 (default: Chinese or English, as the text reads).</source>
        <translation>書的語言：%1（預設：依文字判斷為中文或英文）。</translation>
    </message>
    <message>
        <source>The book&apos;s title (default: its first heading or the file&apos;s name).</source>
        <translation>書名（預設：第一個標題或檔名）。</translation>
    </message>
    <message>
        <source>The book&apos;s author.</source>
        <translation>書的作者。</translation>
    </message>
    <message>
        <source>What reading systems highlight as it is read: sentence or syllable (a character or word).</source>
        <translation>閱讀器在朗讀時標示的單位：sentence（句子）或 syllable（一個字或單字）。</translation>
    </message>
    <message>
        <source>With --say: words per minute (80-450).</source>
        <translation>搭配 --say：每分鐘字數（80-450）。</translation>
    </message>
    <message>
        <source>The book.</source>
        <translation>書。</translation>
    </message>
    <message>
        <source>The text: plain UTF-8 (.txt) or Markdown (.md), whose headings make chapters.</source>
        <translation>文字：純 UTF-8（.txt）或 Markdown（.md），其標題成為章節。</translation>
    </message>
    <message>
        <source>book takes one text file (usage: toonface-cli %1)</source>
        <translation>book 只接受一個文字檔（用法：toonface-cli %1）</translation>
    </message>
    <message>
        <source>book needs either --audio A (a recording of the text) or --say</source>
        <translation>book 需要 --audio A（文字的錄音）或 --say 其中之一</translation>
    </message>
    <message>
        <source>book needs -o BOOK.epub</source>
        <translation>book 需要 -o BOOK.epub</translation>
    </message>
    <message>
        <source>unknown --lang &apos;%1&apos; (%2)</source>
        <translation>不明的 --lang「%1」（%2）</translation>
    </message>
    <message>
        <source>--highlight takes sentence or syllable, not &apos;%1&apos;</source>
        <translation>--highlight 需要 sentence 或 syllable，而不是「%1」</translation>
    </message>
    <message>
        <source>--rate takes a whole number from 80 to 450, not &apos;%1&apos;</source>
        <translation>--rate 需要 80 到 450 的整數，而不是「%1」</translation>
    </message>
    <message>
        <source>%1: %2 %</source>
        <translation>%1：%2 %</translation>
    </message>
    <message>
        <source>%1: %2 chapters, %3 pages, %4 s read aloud</source>
        <translation>%1：%2 章，%3 頁，朗讀 %4 秒</translation>
    </message>
    <message>
        <source>Make a read-aloud EPUB 3 book of a text: each page a paragraph beside the talking face, its sentences highlighted as the recording or the built-in voice reads them.</source>
        <translation>把文字做成有聲的 EPUB 3 書：每頁一個段落，旁邊是說話的臉，錄音或內建語音朗讀時逐句標示。</translation>
    </message>
    <message>
        <source>%1 uses files outside its folder: %2</source>
        <translation>%1 使用了其資料夾以外的檔案：%2</translation>
    </message>
    <message>
        <source>OUT.svg, OUT.html, OUT.mp4, OUT.gif, OUT.webm, OUT.mov, OUT.apng, OUT.webp, or DIR/ for PNG frames.</source>
        <translation>OUT.svg、OUT.html、OUT.mp4、OUT.gif、OUT.webm、OUT.mov、OUT.apng、OUT.webp，或 PNG 影格的 DIR/。</translation>
    </message>
    <message>
        <source>What is behind the face in a video or picture: a colour (white, #rrggbb), transparent, or a photo (default: transparent for WebM, MOV, APNG, WebP and PNG frames, white for MP4 and GIF).</source>
        <translation>影片或圖片中臉後面的東西：顏色（white、#rrggbb）、transparent（透明）或照片（預設：WebM、MOV、APNG、WebP 與 PNG 影格為透明，MP4 與 GIF 為白色）。</translation>
    </message>
    <message>
        <source>Export for a place with limits: %1.</source>
        <translation>為有限制的地方匯出：%1。</translation>
    </message>
    <message>
        <source>Video and pictures: begin this many seconds into the animation.</source>
        <translation>影片與圖片：從動畫的這個秒數開始。</translation>
    </message>
    <message>
        <source>Video and pictures: export this many seconds (default: to the end).</source>
        <translation>影片與圖片：匯出這麼多秒（預設：到結尾）。</translation>
    </message>
    <message>
        <source>animate needs -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|DIR/ ...</source>
        <translation>animate 需要 -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|DIR/ ...</translation>
    </message>
    <message>
        <source>cannot tell the output type of &apos;%1&apos;: use .svg, .html, .mp4, .gif, .webm, .mov, .apng, .webp or a folder ending in /</source>
        <translation>無法判斷「%1」的輸出類型：請使用 .svg、.html、.mp4、.gif、.webm、.mov、.apng、.webp 或以 / 結尾的資料夾</translation>
    </message>
    <message>
        <source>unknown --preset &apos;%1&apos; (%2)</source>
        <translation>不明的 --preset「%1」（%2）</translation>
    </message>
    <message>
        <source>the %1 preset writes %2: name the output .%3, not &apos;%4&apos;</source>
        <translation>%1 預設會寫出 %2：請將輸出命名為 .%3，而不是「%4」</translation>
    </message>
    <message>
        <source>--%1 takes a number of seconds (more than 0 for --duration), not &apos;%2&apos;</source>
        <translation>--%1 需要秒數（--duration 需大於 0），而不是「%2」</translation>
    </message>
    <message>
        <source>--%1 needs a video or picture output; SVG and HTML play the whole animation</source>
        <translation>--%1 需要影片或圖片輸出；SVG 與 HTML 會播放整段動畫</translation>
    </message>
    <message>
        <source>%1; nothing was written (--start and --duration choose a stretch)</source>
        <translation>%1；未寫入任何內容（--start 與 --duration 可選取一段）</translation>
    </message>
    <message>
        <source>Make the face of a photo or project talk, and export the animation (SVG, HTML, MP4, GIF, WebM, MOV, APNG, WebP or PNG frames).</source>
        <translation>讓照片或專案中的臉說話，並匯出動畫（SVG、HTML、MP4、GIF、WebM、MOV、APNG、WebP 或 PNG 影格）。</translation>
    </message>
    <message>
        <source>exporting</source>
        <translation>正在匯出</translation>
    </message>
    <message>
        <source>How the face moves on the pages: svg (an animated drawing) or video (a video of each page read aloud, for reading systems without read-aloud or SVG animation).</source>
        <translation>頁面上的臉如何動：svg（動畫圖）或 video（每一頁朗讀的影片，供不支援朗讀或 SVG 動畫的閱讀器使用）。</translation>
    </message>
    <message>
        <source>--face-as takes svg or video, not &apos;%1&apos;</source>
        <translation>--face-as 需要 svg 或 video，而不是「%1」</translation>
    </message>
    <message>
        <source>copying the sound</source>
        <translation>正在複製聲音</translation>
    </message>
    <message>
        <source>--neutral-frame takes a frame number from 0 or auto, not &apos;%1&apos;</source>
        <translation>--neutral-frame 需要從 0 起算的影格編號或 auto，而不是「%1」</translation>
    </message>
    <message>
        <source>looking for a frame at rest in %1</source>
        <translation>正在 %1 中尋找靜止的影格</translation>
    </message>
    <message>
        <source>%1: neutral frame %2 (mouth closed, eyes open, in a silence; --neutral-frame N names another)</source>
        <translation>%1：中性影格為第 %2 個影格（嘴閉著、眼睜開、無人說話；以 --neutral-frame N 指定其他影格）</translation>
    </message>
    <message>
        <source>%1: neutral frame %2 (mouth closed, eyes open; --neutral-frame N names another)</source>
        <translation>%1：中性影格為第 %2 個影格（嘴閉著、眼睜開；以 --neutral-frame N 指定其他影格）</translation>
    </message>
</context>
</TS>
