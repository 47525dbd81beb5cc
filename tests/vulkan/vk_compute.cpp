#include "vulkan/vk_compute.h"

#include <vulkan/vulkan.h>

#include <cstring>
#include <stdexcept>

#include "io/exr.h"

namespace fl::test::vk {

namespace {

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS)
    throw std::runtime_error(std::string(what) + " failed: VkResult " +
                             std::to_string(static_cast<int>(r)));
}

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

}  // namespace

struct Device::State {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  std::string driver;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;

  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(physical, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
    throw std::runtime_error("no Vulkan memory type with the properties needed");
  }
  Buffer buffer(VkDeviceSize size, VkBufferUsageFlags usage) const {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = size;
    bi.usage = usage;
    check(vkCreateBuffer(device, &bi, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, b.buffer, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                             VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkAllocateMemory(device, &ai, nullptr, &b.memory), "vkAllocateMemory");
    check(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
    return b;
  }
  void write(const Buffer& b, const void* data, size_t bytes) const {
    void* p = nullptr;
    check(vkMapMemory(device, b.memory, 0, b.size, 0, &p), "vkMapMemory");
    std::memcpy(p, data, bytes);
    vkUnmapMemory(device, b.memory);
  }
  void free(Buffer& b) const {
    vkDestroyBuffer(device, b.buffer, nullptr);
    vkFreeMemory(device, b.memory, nullptr);
  }
  void free(Image& i) const {
    vkDestroyImageView(device, i.view, nullptr);
    vkDestroyImage(device, i.image, nullptr);
    vkFreeMemory(device, i.memory, nullptr);
  }
  VkCommandBuffer begin() const {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cb;
    check(vkAllocateCommandBuffers(device, &ai, &cb), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cb, &bi), "vkBeginCommandBuffer");
    return cb;
  }
  void submit(VkCommandBuffer cb) const {
    check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cb;
    check(vkQueueSubmit(queue, 1, &si, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(queue), "vkQueueWaitIdle");
    vkFreeCommandBuffers(device, pool, 1, &cb);
  }
  Image upload(const Texture& t, Storage storage) const;
};

namespace {

void create_instance(Device::State& s) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "fresnel-lab shader tests";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ci.pApplicationInfo = &app;
  check(vkCreateInstance(&ci, nullptr, &s.instance), "vkCreateInstance (no Vulkan loader/driver?)");
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(s.instance, &n, nullptr);
  if (n == 0) throw std::runtime_error("no Vulkan device found (install mesa-vulkan-drivers)");
  std::vector<VkPhysicalDevice> devices(n);
  vkEnumeratePhysicalDevices(s.instance, &n, devices.data());
  s.physical = devices.front();
  vkGetPhysicalDeviceProperties(s.physical, &s.props);
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &driver;
  vkGetPhysicalDeviceProperties2(s.physical, &p2);
  const auto v = s.props.apiVersion;
  s.driver = std::string("driver ") + driver.driverName + ", Vulkan " +
             std::to_string(VK_API_VERSION_MAJOR(v)) + "." +
             std::to_string(VK_API_VERSION_MINOR(v)) + "." +
             std::to_string(VK_API_VERSION_PATCH(v)) + ", conformance " +
             std::to_string(driver.conformanceVersion.major) + "." +
             std::to_string(driver.conformanceVersion.minor) + "." +
             std::to_string(driver.conformanceVersion.subminor) + "." +
             std::to_string(driver.conformanceVersion.patch);
}

void create_device(Device::State& s) {
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(s.physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(s.physical, &n, families.data());
  bool found = false;
  for (uint32_t i = 0; i < n && !found; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) s.family = i, found = true;
  if (!found) throw std::runtime_error("the Vulkan device has no compute queue");
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qi.queueFamilyIndex = s.family;
  qi.queueCount = 1;
  qi.pQueuePriorities = &priority;
  VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  di.queueCreateInfoCount = 1;
  di.pQueueCreateInfos = &qi;
  check(vkCreateDevice(s.physical, &di, nullptr, &s.device), "vkCreateDevice");
  vkGetDeviceQueue(s.device, s.family, 0, &s.queue);
  VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pi.queueFamilyIndex = s.family;
  check(vkCreateCommandPool(s.device, &pi, nullptr, &s.pool), "vkCreateCommandPool");
  // How engines sample lookup tables: bilinear, clamp to edge, no mipmaps.
  VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  si.magFilter = si.minFilter = VK_FILTER_LINEAR;
  si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  si.maxLod = 0.0f;
  check(vkCreateSampler(s.device, &si, nullptr, &s.sampler), "vkCreateSampler");
}

void transition(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to,
                VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags src_stage,
                VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.oldLayout = from;
  b.newLayout = to;
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The texels as the format stores them: floats, or IEEE half bit patterns (round to nearest even).
std::vector<unsigned char> texel_bytes(const Texture& t, Storage storage) {
  std::vector<unsigned char> out;
  if (storage == Storage::Float) {
    out.resize(t.rgba.size() * sizeof(float));
    std::memcpy(out.data(), t.rgba.data(), out.size());
    return out;
  }
  std::vector<std::uint16_t> half(t.rgba.size());
  for (size_t k = 0; k < half.size(); ++k) half[k] = io::half_bits(t.rgba[k]);
  out.resize(half.size() * sizeof(std::uint16_t));
  std::memcpy(out.data(), half.data(), out.size());
  return out;
}

}  // namespace

Image Device::State::upload(const Texture& t, Storage storage) const {
  const VkFormat format =
      storage == Storage::Half ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R32G32B32A32_SFLOAT;
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(physical, format, &fp);
  if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
    throw std::runtime_error(std::string("the device cannot filter ") + storage_name(storage) +
                             " RGBA textures linearly");
  Image img;
  VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ii.imageType = VK_IMAGE_TYPE_2D;
  ii.format = format;
  ii.extent = {uint32_t(t.width), uint32_t(t.height), 1};
  ii.mipLevels = ii.arrayLayers = 1;
  ii.samples = VK_SAMPLE_COUNT_1_BIT;
  ii.tiling = VK_IMAGE_TILING_OPTIMAL;
  ii.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device, &ii, nullptr, &img.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, img.image, &req);
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = memory_type(req.memoryTypeBits, 0);
  check(vkAllocateMemory(device, &ai, nullptr, &img.memory), "vkAllocateMemory");
  check(vkBindImageMemory(device, img.image, img.memory, 0), "vkBindImageMemory");
  const auto bytes = texel_bytes(t, storage);
  Buffer staging = buffer(bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  write(staging, bytes.data(), bytes.size());
  VkCommandBuffer cb = begin();
  transition(cb, img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
             VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
             VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = ii.extent;
  vkCmdCopyBufferToImage(cb, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &copy);
  transition(cb, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  submit(cb);
  free(staging);
  VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vi.image = img.image;
  vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
  vi.format = format;
  vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  check(vkCreateImageView(device, &vi, nullptr, &img.view), "vkCreateImageView");
  return img;
}

Device::Device() : s_(std::make_unique<State>()) {
  create_instance(*s_);
  create_device(*s_);
}

Device::~Device() {
  if (s_->device) {
    vkDestroySampler(s_->device, s_->sampler, nullptr);
    vkDestroyCommandPool(s_->device, s_->pool, nullptr);
    vkDestroyDevice(s_->device, nullptr);
  }
  if (s_->instance) vkDestroyInstance(s_->instance, nullptr);
}

std::string Device::name() const {
  return s_->props.deviceName;
}
std::string Device::driver() const {
  return s_->driver;
}

namespace {

// The job's descriptor set layout: see ComputeJob.
std::vector<VkDescriptorSetLayoutBinding> job_bindings(const ComputeJob& job) {
  std::vector<VkDescriptorSetLayoutBinding> b;
  auto add = [&](VkDescriptorType type) {
    b.push_back({uint32_t(b.size()), type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  };
  add(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  add(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  for (size_t k = 0; k < job.textures.size(); ++k)
    add(job.separate_sampler ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                             : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  if (job.separate_sampler && !job.textures.empty()) add(VK_DESCRIPTOR_TYPE_SAMPLER);
  return b;
}

// Vulkan objects of one dispatch, destroyed together.
struct Pipeline {
  VkDevice device;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkShaderModule module = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  ~Pipeline() {
    vkDestroyDescriptorPool(device, pool, nullptr);
    vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyShaderModule(device, module, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
  }
};

void make_pipeline(Pipeline& p, const ComputeJob& job,
                   const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  li.bindingCount = uint32_t(bindings.size());
  li.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(p.device, &li, nullptr, &p.set_layout),
        "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &p.set_layout;
  check(vkCreatePipelineLayout(p.device, &pli, nullptr, &p.layout), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo mi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  mi.codeSize = job.spirv.size() * 4;
  mi.pCode = job.spirv.data();
  check(vkCreateShaderModule(p.device, &mi, nullptr, &p.module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = p.module;
  ci.stage.pName = "main";
  ci.layout = p.layout;
  check(vkCreateComputePipelines(p.device, VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline),
        "vkCreateComputePipelines");
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& b : bindings) sizes.push_back({b.descriptorType, 1});
  VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpi.maxSets = 1;
  dpi.poolSizeCount = uint32_t(sizes.size());
  dpi.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(p.device, &dpi, nullptr, &p.pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = p.pool;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &p.set_layout;
  check(vkAllocateDescriptorSets(p.device, &ai, &p.set), "vkAllocateDescriptorSets");
}

}  // namespace

std::vector<float> Device::run(const ComputeJob& job) {
  const auto bindings = job_bindings(job);
  Pipeline p{s_->device};
  make_pipeline(p, job, bindings);
  const size_t in_bytes = std::max<size_t>(16, job.inputs.size() * 4),
               out_bytes = std::max<size_t>(16, size_t(job.invocations) * 16);
  Buffer in = s_->buffer(in_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer out = s_->buffer(out_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  s_->write(in, job.inputs.data(), job.inputs.size() * 4);
  std::vector<Image> images;
  for (const auto* t : job.textures) images.push_back(s_->upload(*t, job.storage));
  std::vector<VkDescriptorBufferInfo> buffers{{in.buffer, 0, in_bytes}, {out.buffer, 0, out_bytes}};
  std::vector<VkDescriptorImageInfo> infos;
  for (const auto& img : images)
    infos.push_back({job.separate_sampler ? VK_NULL_HANDLE : s_->sampler, img.view,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  infos.push_back({s_->sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
  std::vector<VkWriteDescriptorSet> writes;
  for (const auto& b : bindings) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = p.set;
    w.dstBinding = b.binding;
    w.descriptorCount = 1;
    w.descriptorType = b.descriptorType;
    if (b.binding < 2)
      w.pBufferInfo = &buffers[b.binding];
    else
      w.pImageInfo = &infos[std::min<size_t>(b.binding - 2, infos.size() - 1)];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(s_->device, uint32_t(writes.size()), writes.data(), 0, nullptr);
  VkCommandBuffer cb = s_->begin();
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
  vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0, 1, &p.set, 0, nullptr);
  vkCmdDispatch(cb, (job.invocations + 63) / 64, 1, 1);
  s_->submit(cb);
  std::vector<float> result(size_t(job.invocations) * 4);
  void* mapped = nullptr;
  check(vkMapMemory(s_->device, out.memory, 0, out_bytes, 0, &mapped), "vkMapMemory");
  std::memcpy(result.data(), mapped, result.size() * 4);
  vkUnmapMemory(s_->device, out.memory);
  for (auto& img : images) s_->free(img);
  s_->free(in);
  s_->free(out);
  return result;
}

Device& shared_device() {
  static Device d;
  return d;
}

}  // namespace fl::test::vk
