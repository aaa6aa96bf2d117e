return createImpulseLabCheck;
};
var createImpulseLabCheck = impulselabCheckModule();
